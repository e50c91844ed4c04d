"""Reading a text again after edits in many places gives what parsing it from nothing gives.

``reread`` (a migration's pass made the edits) lexes again only the physical lines the edits
touched, groups and parses again the logical lines around them (a DIM list continued over
lines, a ``\\r`` that meets a ``\\n``), and takes every other line over, moved by the edits
above it; where it cannot be sure of that it says so (None), and the text is parsed.
"""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import mintlang
from mintlang.syntax.parser import Document
from mintlang.syntax.reread import Replaced, reread
from tests.corpus_files import CorpusCase, cases
from tests.fuzzing import examples

CASES = cases("v3/programs")
WRITTEN = ["", "x", "1", " ", ":", ",", "\n", "\r", "\r\n", "REM MIGRATE: X-V3: note\n", "DIM a(3),\n", "b(2)\n"]
WRITTEN += [" : GO", "SPEED.0 = 1\n", "IF a THEN ", "ENDIF\n", "#here\n", "a = 1 AND b OR c\n", '"', "@"]


def _same(again: Document, whole: Document) -> None:
    assert again.source == whole.source
    assert list(again.physical) == list(whole.physical)
    assert list(again.tokens) == list(whole.tokens)
    assert again.placed == whole.placed
    assert again.diagnostics == whole.diagnostics
    assert (again.definitions, again.expansions, dict(again.macros)) == (whole.definitions, whole.expansions, {})
    assert [again.line_index.position(offset) for offset in range(len(again.source) + 1)] == [
        whole.line_index.position(offset) for offset in range(len(whole.source) + 1)
    ]


def _edited(source: str, edits: list[tuple[float, int, str]]) -> tuple[str, list[Replaced]]:
    """``source`` with ``edits`` made at once, as a pass makes them: each at its place (a fraction of the text),
    removing so many characters, those that would overlap an earlier one left out."""
    made: list[Replaced] = []
    parts: list[str] = []
    position = 0
    for where, removed, written in sorted(edits):
        start = int(where * len(source))
        end = min(start + removed, len(source))
        if start < position:
            continue
        parts += (source[position:start], written)
        made.append((start, end, len(written)))
        position = end
    parts.append(source[position:])
    return "".join(parts), made


@settings(max_examples=examples(150), deadline=None)
@given(
    case=st.sampled_from(CASES),
    passes=st.lists(
        st.lists(
            st.tuples(st.floats(min_value=0, max_value=1), st.integers(0, 12), st.sampled_from(WRITTEN)), max_size=25
        ),
        min_size=1,
        max_size=3,
    ),
)
def test_a_reread_after_a_pass_of_edits_equals_a_parse_of_the_new_text(
    case: CorpusCase, passes: list[list[tuple[float, int, str]]]
) -> None:
    """Pass after pass, each reading taken over from the last one where it could be."""
    source = case.source
    document = mintlang.parse(source, "v3")
    for edits in passes:
        source, made = _edited(source, edits)
        whole = mintlang.parse(source, "v3")
        again = reread(document, source, made)
        if again is not None:
            _same(again, whole)
        document = again or whole


@pytest.mark.parametrize(
    ("before", "edits", "after"),
    [
        pytest.param(
            "a = 1\nb = 2\nc = 3\n", [(4, 5, 2), (16, 17, 2)], "a = 10\nb = 2\nc = 30\n", id="two lines apart"
        ),
        pytest.param("DIM a(3) = 1,\n2, 3\nc = 1\n", [(14, 15, 1)], "DIM a(3) = 1,\n5, 3\nc = 1\n", id="in a DIM list"),
        pytest.param("a = 1\rb = 2\n", [(6, 6, 1)], "a = 1\r\nb = 2\n", id="a line end between CR and LF"),
        pytest.param("a = 1\nb = 2\n", [(0, 0, 18)], "REM MIGRATE: X: y\na = 1\nb = 2\n", id="a line above the first"),
        pytest.param("a = 1\nb = 2", [(11, 11, 4)], "a = 1\nb = 2\nGO\n", id="after a last line unended"),
    ],
)
def test_a_reread_equals_a_parse(before: str, edits: list[Replaced], after: str) -> None:
    again = reread(mintlang.parse(before, "v3"), after, edits)
    assert again is not None
    _same(again, mintlang.parse(after, "v3"))


def test_a_line_no_edit_touched_is_taken_over_moved_not_parsed_again() -> None:
    before = mintlang.parse("a = 1\nb = 2\nc = 3\n", "v3")
    after = reread(before, "a = 12\nb = 2\nc = 34\n", [(5, 5, 1), (17, 17, 1)])
    assert after is not None
    assert after.placed[1].syntax is before.placed[1].syntax
    assert after.placed[1].origin == before.placed[1].origin + 1


@pytest.mark.parametrize(
    ("before", "after", "edits"),
    [
        pytest.param(
            "a = @\nb = 1\n", "a = @\nb = 2\n", [(10, 11, 1)], id="the earlier reading found a character v3 lacks"
        ),
        pytest.param("a = 1\nb = 1\n", "a = 1\nb = (\n", [(10, 11, 1)], id="an edit writes a line v3 cannot read"),
    ],
)
def test_what_a_reading_reports_is_read_afresh(before: str, after: str, edits: list[Replaced]) -> None:
    assert reread(mintlang.parse(before, "v3"), after, edits) is None
