"""Re-parsing a new version from the previous one gives what parsing it from nothing gives.

``reparse`` reads again only the physical lines an edit touched and the logical
lines around them (a DIM list continued over lines, a ``\\r`` that meets a
``\\n``), and takes every other line over, moved by the edit's length.
"""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

import mintlang
from mintlang.syntax.parser import Document
from mintlang.syntax.reparse import reparse
from tests.corpus_files import CorpusCase, cases
from tests.fuzzing import examples

CASES = [case for folder in ("v4/valid", "v4/invalid", "mintmt") for case in cases(folder)]
TYPED = ["x", "1", " ", ":", ",", "\n", "\r", "\r\n", "REM ", "DIM a(3) = 1,\n", "DEFINE k = 2\n", "k", "IF ", '"']


def _same(incremental: Document, whole: Document) -> None:
    assert incremental.source == whole.source
    assert list(incremental.physical) == list(whole.physical)
    assert list(incremental.tokens) == list(whole.tokens)
    assert incremental.placed == whole.placed
    assert incremental.diagnostics == whole.diagnostics
    assert incremental.definitions == whole.definitions
    assert incremental.expansions == whole.expansions
    assert dict(incremental.macros) == dict(whole.macros)


def _edited(source: str, where: float, removed: int, typed: str) -> str:
    offset = int(where * len(source))
    return source[:offset] + typed + source[offset + removed :]


@settings(max_examples=examples(120), deadline=None)
@given(
    case=st.sampled_from(CASES),
    copies=st.integers(1, 4),
    edits=st.lists(
        st.tuples(st.floats(min_value=0, max_value=1), st.integers(0, 12), st.sampled_from(["", *TYPED])),
        min_size=1,
        max_size=30,
    ),
)
def test_a_reparse_after_any_run_of_edits_equals_a_parse_of_the_new_text(
    case: CorpusCase, copies: int, edits: list[tuple[float, int, str]]
) -> None:
    """Each edit elsewhere adds pieces to the moved lines, until they are made into one tuple again."""
    source = "\n".join([case.source] * copies)
    document = mintlang.parse(source, case.dialect, controller=case.controller)
    for where, removed, typed in edits:
        source = _edited(source, where, removed, typed)
        document = reparse(document, source, case.dialect, controller=case.controller)
        _same(document, mintlang.parse(source, case.dialect, controller=case.controller))


def test_a_line_below_the_edit_is_taken_over_moved_not_parsed_again() -> None:
    before = mintlang.parse("DIM a\na = 1\nPRINT a\n")
    after = reparse(before, "DIM a\na = 12\nPRINT a\n")
    assert after.change is not None
    assert (after.change.first_line, after.change.old_lines, after.change.new_lines) == (1, 1, 1)
    assert after.placed[2].syntax is before.placed[2].syntax
    assert after.placed[2].origin == before.placed[2].origin + 1


def test_a_dim_list_that_an_edit_continues_takes_the_next_line_in() -> None:
    before = mintlang.parse("DIM a(3) = 1, 2\n3\n")
    after = reparse(before, "DIM a(3) = 1, 2,\n3\n")
    _same(after, mintlang.parse("DIM a(3) = 1, 2,\n3\n"))
    assert len(after.placed) == 1


def test_a_line_end_written_between_cr_and_lf_joins_them() -> None:
    before = mintlang.parse("a = 1\rb = 2\n")
    after = reparse(before, "a = 1\r\nb = 2\n")
    _same(after, mintlang.parse("a = 1\r\nb = 2\n"))


def test_a_new_definition_makes_it_a_parse_of_the_whole_text() -> None:
    before = mintlang.parse("REM\nPRINT k\n")
    after = reparse(before, "DEFINE k = 2\nPRINT k\n")
    assert after.change is None
    _same(after, mintlang.parse("DEFINE k = 2\nPRINT k\n"))


def test_another_dialect_or_controller_makes_it_a_parse_of_the_whole_text() -> None:
    before = mintlang.parse("PRINT 1\n")
    assert reparse(before, "PRINT 2\n", "v3").change is None
    assert reparse(before, "PRINT 2\n", controller="mintdrive").change is None
