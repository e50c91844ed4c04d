"""``mint check --fix`` keeps a file's line ends, as ``mint format`` does: a line a fix adds (a DIM, a created
subroutine, an END) ends as the file's lines end, \\r\\n, \\n or a lone \\r (a line end Mint reads as the
others), so a file never comes back with two kinds."""

from __future__ import annotations

import re

from hypothesis import given, settings
from hypothesis import strategies as st

from mintlang import check
from mintlang.fixes import fix_text
from tests.core.test_fixes import WRITTEN
from tests.fuzzing import examples


@settings(max_examples=examples(200))
@given(st.lists(st.sampled_from(WRITTEN), min_size=2, max_size=8), st.sampled_from(["\r\n", "\r", "\n"]))
def test_every_line_a_fix_adds_ends_as_the_files_lines_end(lines: list[str], newline: str) -> None:
    fixed = fix_text(newline.join(lines) + newline, check, unsafe=True).text
    assert set(re.findall(r"\r\n|\r|\n", fixed)) == {newline}
