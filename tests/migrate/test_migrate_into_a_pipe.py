"""``mint-migrate | head -1``: a reader that stops reading ends mint-migrate quietly with 141.

As mint check, mint test and mint-run do: not 0 as if the whole report had been read (one large
write of a JSON report into the pipe used to lose the rest without a word), nor 1, which says the
gate failed, nor a traceback. The guide's v3 programs (the corpus) make a diff and a JSON report far
larger than a pipe's buffer; the default mode writes nothing.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.reader_leaves import BROKEN_PIPE, first_line_then_hang_up

V3_PROGRAMS = Path(__file__).parents[1] / "corpus" / "v3" / "programs"


@pytest.mark.parametrize(("output_format", "first"), [("json", "{\n"), ("text", "--- a/")])
def test_a_report_cut_short_by_its_reader_ends_with_the_broken_pipe_status(output_format: str, first: str) -> None:
    line, status, stderr = first_line_then_hang_up("migrate", "--format", output_format, str(V3_PROGRAMS))
    assert line.startswith(first)
    assert status == BROKEN_PIPE
    assert "Traceback" not in stderr and "Exception ignored" not in stderr
