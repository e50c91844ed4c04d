"""After an edit, only the lines it touched are parsed, indexed and checked again.

The syntax of a line is position-free (its spans count from the start of its
first physical line), so an unchanged line keeps its syntax wherever the edit
moved it, and the analyser keeps what it found there. Whatever the caches hold,
a check must report exactly what a check from nothing reports.
"""

from __future__ import annotations

from dataclasses import fields, is_dataclass

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import mintlang
from mintlang.diagnostics import Span
from mintlang.semantic.symbols import Unit
from mintlang.syntax import nodes as n
from tests.corpus_files import CorpusCase, cases
from tests.fuzzing import examples

CASES = [case for folder in ("v4/valid", "v4/invalid") for case in cases(folder)]
MACRO_CASES = [case for case in CASES if "DEFINE" in case.source.upper()]
TYPED = ["x", "1", " ", ":", ",", ";", "(", ")", '"', "'", "#", "\n", "\r\n", "REM ", "DIM ", "IF ", "ENDIF"]


def _check(case: CorpusCase, source: str, previous: mintlang.Analysis | None = None) -> mintlang.Analysis:
    return mintlang.check_application(
        source, dialect=case.dialect, controller=case.controller, config=case.configuration, previous=previous
    )


def _same(warm: mintlang.Analysis, cold: mintlang.Analysis) -> None:
    assert warm.program == cold.program
    assert warm.configuration == cold.configuration
    assert warm.model.program.lines == cold.model.program.lines
    assert warm.model.structures[Unit.PROGRAM] == cold.model.structures[Unit.PROGRAM]
    assert list(warm.model.lines.facts()) == list(cold.model.lines.facts())  # spliced after an edit
    occurrences = [(symbol.identity, list(symbol.occurrences())) for symbol in warm.model.symbols.all()]
    assert occurrences == [(symbol.identity, list(symbol.occurrences())) for symbol in cold.model.symbols.all()]


def test_a_line_below_an_edit_keeps_its_syntax_at_its_new_place() -> None:
    source = "DIM speed\nspeed = 10\nJOG.0 = speed\n"
    before = mintlang.parse(source)
    after = mintlang.parse("REM moved\n" + source)
    assert after.placed[-1].syntax is before.placed[-1].syntax
    assert after.placed[-1].origin == before.placed[-1].origin + len("REM moved\n")
    assert after.placed[-1].number == before.placed[-1].number + 1


def test_a_line_that_names_a_macro_is_parsed_again_when_the_macro_changes() -> None:
    before = mintlang.parse("DEFINE gain = 2\nKPROP.0 = gain\n")
    after = mintlang.parse("DEFINE gain = 3\nKPROP.0 = gain\n")
    assert after.placed[-1].syntax is not before.placed[-1].syntax
    value = after.lines[-1].statements[0].values[0]  # type: ignore[union-attr]
    assert value.value == 3


def _written(node: object) -> list[tuple[str, Span]]:
    """Every literal and name in a tree, with its span."""
    found: list[tuple[str, Span]] = []
    if isinstance(node, tuple):
        for item in node:
            found.extend(_written(item))
    elif is_dataclass(node):
        if isinstance(node, n.Number | n.StringLiteral | n.Name):
            found.append((node.text, node.span))
        for field in fields(node):
            found.extend(_written(getattr(node, field.name)))
    return found


@pytest.mark.parametrize("case", [case for case in CASES if case not in MACRO_CASES], ids=lambda case: case.name)
def test_every_literal_and_name_of_the_tree_with_file_offsets_spans_its_own_text(case: CorpusCase) -> None:
    source = case.source
    for written, span in _written(mintlang.parse(source, case.dialect).lines):
        assert source[span.start : span.end].removeprefix("#") == written  # a label's span holds its '#'


def test_a_dim_list_continued_past_a_comment_is_placed_by_the_comment_s_length() -> None:
    short = "DIM a(3) = 1,\nREM c\n2, 3\n"
    long = "DIM a(3) = 1,\nREM a longer comment\n2, 3\n"
    mintlang.parse(short)
    for source in (short, long):
        value = mintlang.parse(source).lines[0].statements[0].values[1]  # type: ignore[union-attr]
        assert source[value.span.start : value.span.end] == "2"


def test_the_analyser_reads_only_the_position_free_syntax() -> None:
    analysis = mintlang.check_application("DIM a\na = 1\nIF a > 0 DO\n  PRINT a\nENDIF\n")
    assert "lines" not in vars(analysis.model.program)  # the tree with file offsets is made for tools only
    assert "index" not in vars(analysis.model)


def test_the_tree_with_file_offsets_matches_the_text() -> None:
    source = "REM top\n  DIM speed\n  speed = 10 : JOG.0 = speed\n"
    line = mintlang.parse(source).lines[-1]
    assert source[line.span.start : line.span.end] == "speed = 10 : JOG.0 = speed"
    jog = line.statements[1]
    assert source[jog.span.start : jog.span.end] == "JOG.0 = speed"


def _edit_and_compare(case: CorpusCase, where: float, removed: int, typed: str) -> None:
    before = _check(case, case.source)  # the caches now hold every line of the file before the edit
    offset = int(where * len(case.source))
    edited = case.source[:offset] + typed + case.source[offset + removed :]
    warm = _check(case, edited)
    from_before = _check(case, edited, previous=before)  # as the language server checks a keystroke
    mintlang.clear_caches()
    cold = _check(case, edited)
    _same(warm, cold)
    _same(from_before, cold)


@given(
    case=st.sampled_from(CASES),
    where=st.floats(min_value=0, max_value=1),
    removed=st.integers(min_value=0, max_value=3),
    typed=st.sampled_from(["", *TYPED]),
)
def test_a_check_after_an_edit_reports_what_a_check_from_nothing_reports(
    case: CorpusCase, where: float, removed: int, typed: str
) -> None:
    _edit_and_compare(case, where, removed, typed)


@given(
    case=st.sampled_from(MACRO_CASES),
    where=st.floats(min_value=0, max_value=1),
    removed=st.integers(min_value=0, max_value=1),
    typed=st.sampled_from(["", "1", "x", " ", ".", ","]),
)
def test_an_edit_to_a_macro_changes_every_line_that_uses_it(
    case: CorpusCase, where: float, removed: int, typed: str
) -> None:
    _edit_and_compare(case, where, removed, typed)


PROGRAM = "DIM feed\nREM set-up\nfeed = 10\nJOG.0 = feed : REM the jog\nPRINT feed\nGOSUB missing\n"


def test_typing_in_a_comment_carries_the_model_and_its_findings_over() -> None:
    before = mintlang.check_application(PROGRAM)
    after = mintlang.check_application(PROGRAM.replace("set-up", "set up"), previous=before)
    assert after.model.carried is not None
    assert after.model.carried.same_facts
    assert "symbols" not in vars(after.model)  # no symbol table was needed to check the keystroke
    assert after.program == mintlang.check_application(PROGRAM.replace("set-up", "set up")).program
    moved = mintlang.check_application(PROGRAM.replace("the jog", "the jog, longer"), previous=before)
    (missing,) = before.program  # E3004: no label #missing
    assert [d.span.start for d in moved.program] == [missing.span.start + len(", longer")]


def test_typing_in_a_number_carries_the_findings_over_unless_a_pass_reads_its_value() -> None:
    before = mintlang.check_application(PROGRAM)
    jog = mintlang.check_application(PROGRAM.replace("feed = 10", "feed = 105"), previous=before)
    assert jog.model.carried is not None
    assert jog.model.carried.same_facts  # no whole-application pass reads what feed is set to
    array = "DIM table(3)\ntable(2) = 1\nPRINT table(2)\n"
    resized = mintlang.check_application(array.replace("(3)", "(1)"), previous=mintlang.check_application(array))
    assert resized.model.carried is not None
    assert not resized.model.carried.same_facts  # the size of an array: table(2) is now outside it
    assert [d.code for d in resized.program] == ["E2016", "E2016"]  # table(2) written and read: 1 element


def test_a_name_typed_in_a_line_that_cannot_be_parsed_is_read_again() -> None:
    """Equal facts are not enough: the words of a broken line count as uses of those names (W103)."""
    source = "DIM xx\nDIM yy\nq = (xx\nPRINT 2\n"
    edited = source.replace("(xx", "(yy")
    after = mintlang.check_application(edited, previous=mintlang.check_application(source))
    assert after.program == mintlang.check_application(edited).program
    assert [d.message for d in after.program if d.code == "W103"] == ["variable 'xx' is declared but never used"]


def test_typing_in_a_name_carries_the_blocks_and_checks_the_whole_application_again() -> None:
    before = mintlang.check_application(PROGRAM)
    after = mintlang.check_application(PROGRAM.replace("PRINT feed", "PRINT feedx"), previous=before)
    assert after.model.carried is not None
    assert not after.model.carried.same_facts
    assert after.model.structures[Unit.PROGRAM].blocks is before.model.structures[Unit.PROGRAM].blocks
    assert after.program == mintlang.check_application(PROGRAM.replace("PRINT feed", "PRINT feedx")).program
    assert len(after.program) == len(before.program) + 1  # feedx is not declared


_COMMENTED = [case for case in CASES if case.configuration is None]
_TYPED_IN_COMMENTS = ["x", " ", "", "\t", "REM mint: ignore[E2001]", "ENDIF", "1", ":", "0", ".", "(", "a"]


@st.composite
def _keystrokes(draw: st.DrawFn, source: str) -> tuple[int, int, str]:
    """Where a user types: mostly in a comment, in a number or at the end of a line, sometimes anywhere."""
    lines = source.split("\n")
    number = draw(st.integers(0, len(lines) - 1))
    line = lines[number]
    comment = line.upper().find("REM")
    after_digits = [column + 1 for column, character in enumerate(line) if character.isdigit()]
    column = draw(
        st.sampled_from(
            [
                len(line),
                *([comment + 3, len(line)] if comment >= 0 else []),
                *after_digits[:3],
                draw(st.integers(0, len(line))),
            ]
        )
    )
    offset = sum(len(earlier) + 1 for earlier in lines[:number]) + column
    return offset, draw(st.integers(0, 2)), draw(st.sampled_from(_TYPED_IN_COMMENTS))


@settings(max_examples=examples(60), deadline=None)
@given(programs=st.lists(st.sampled_from(_COMMENTED), min_size=2, max_size=5), data=st.data())
def test_a_check_carried_over_a_run_of_keystrokes_reports_what_a_check_from_nothing_reports(
    programs: list[CorpusCase], data: st.DataObject
) -> None:
    """As the language server checks: each version from the one before, on a file with findings above
    and below the keystrokes (several corpus programs, valid and not, one after the other)."""
    case = programs[0]
    source = "\n".join(program.source for program in programs)
    previous = _check(case, source)
    for _ in range(6):
        offset, removed, typed = data.draw(_keystrokes(source))
        source = source[:offset] + typed + source[offset + removed :]
        previous = _check(case, source, previous=previous)
        _same(previous, _check(case, source))
