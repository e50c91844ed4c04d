"""``mint check --fix`` never writes a syntax error the text did not have, as ruff reverts a fix that
introduces one: a respelling that fits no statement (``the`` as ``THEN``, which only follows an IF's
condition, 000:1570-1577) is a guess that would leave the program unreadable to the compiler. A round
of fixes after which the text has more syntax errors (2003, 2004, 2006-2008: a statement the compiler
cannot read as written, 000:18920-18958) is undone and tried again without the fixes that add them;
the others apply."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from mintlang import check
from mintlang.codes import SYNTAX_ERRORS
from mintlang.diagnostics import Diagnostic, Edit, Fix, Severity, Span
from mintlang.fixes import ADDS_SYNTAX_ERROR, fix_text, left_out
from tests.fuzzing import examples


def syntax_errors(text: str) -> int:
    return sum(diagnostic.mint_error in SYNTAX_ERRORS for diagnostic in check(text))


def test_a_respelling_that_fits_no_statement_is_not_written() -> None:
    source = "DIM a\nthe a = 1\nprnt a\n"  # 'the' is offered THEN, 'prnt' PRINT: both unsafe respellings
    result = fix_text(source, check, unsafe=True)
    assert result.text == "DIM a\nthe a = 1\nPRINT a\n"
    assert [d.code for d in result.remaining] == ["E3007"]  # still reported, with its fix for a person to judge


def test_only_the_fix_that_adds_a_syntax_error_is_left_out() -> None:
    def findings(text: str) -> tuple[Diagnostic, ...]:
        """'x' is fixed as 'PRINT 1'; 'y' as '(' which the compiler cannot read."""
        found = [diagnostic for diagnostic in check(text) if diagnostic.mint_error in SYNTAX_ERRORS]
        for word, new in (("x", "PRINT 1"), ("y", "(")):
            if (at := text.find(word)) >= 0:
                fix = Fix(f"write {new}", (Edit(Span(at, at + 1), new),), safe=True)
                found.append(Diagnostic("W101", Severity.WARNING, Span(at, at + 1), word, fixes=(fix,)))
        return tuple(found)

    assert fix_text("x\ny\n", findings, unsafe=False).text == "PRINT 1\ny\n"


WORDS = ["the", "prnt", "lop", "endl", "nxt", "a", "=", "1", "to", "fr", "gosb", "#", ":", "idl[0]", "pause"]


@settings(max_examples=examples(60))
@given(st.lists(st.lists(st.sampled_from(WORDS), min_size=1, max_size=5).map(" ".join), max_size=4))
def test_fixing_adds_no_syntax_error(lines: list[str]) -> None:
    source = "DIM a\n" + "".join(f"{line}\n" for line in lines)
    assert syntax_errors(fix_text(source, check, unsafe=True).text) <= syntax_errors(source)


def test_the_fix_set_aside_is_kept_with_why() -> None:
    # what --fix leaves out is said, not counted as fixable: 'the' respelt THEN fits no statement (000:1570-1577)
    result = fix_text("DIM a\nthe a = 1\nprnt a\n", check, unsafe=True)
    assert [(code, why) for (code, _), why in result.left_out] == [("E3007", ADDS_SYNTAX_ERROR)]


def test_before_any_fixing_the_fixes_the_first_round_sets_aside_are_found_as_fixing_finds_them() -> None:
    source = "DIM a\nthe a = 1\nprnt a\n"
    assert left_out(source, check(source), check) == dict(fix_text(source, check, unsafe=True).left_out)
    assert left_out("DIM a\nprnt a\n", check("DIM a\nprnt a\n"), check) == {}  # PRINT a: nothing set aside


def test_the_fix_that_adds_a_syntax_error_is_found_in_few_checks() -> None:
    # 64 fixes that are sound and one that writes "(": each fix tried alone took a check per fix, 65 more; the
    # line that has a syntax error more names the one fix that changed it
    checks: list[str] = []

    def findings(text: str) -> tuple[Diagnostic, ...]:
        checks.append(text)
        found = [diagnostic for diagnostic in check(text) if diagnostic.mint_error in SYNTAX_ERRORS]
        for at, word in enumerate(text):
            if word in "xy":
                new = "1" if word == "x" else "("
                fix = Fix(f"write {new}", (Edit(Span(at, at + 1), new),), safe=True)
                found.append(Diagnostic("W101", Severity.WARNING, Span(at, at + 1), word, fixes=(fix,)))
        return tuple(found)

    source = "DIM a\n" + "a = x\n" * 32 + "a = y\n" + "a = x\n" * 32
    result = fix_text(source, findings, unsafe=False)
    assert result.text == source.replace("x", "1")
    assert len(checks) <= 4  # the text, the round, the round again without it, and the text found fixed


def test_a_syntax_error_one_fix_mends_does_not_hide_one_another_adds() -> None:
    def findings(text: str) -> tuple[Diagnostic, ...]:
        """'a = ((' (a syntax error, 000:18920-18923) is fixed as 'a = 1'; 'PRINT 2' as '(', one."""
        found = [diagnostic for diagnostic in check(text) if diagnostic.mint_error in SYNTAX_ERRORS]
        for old, new in (("a = ((", "a = 1"), ("PRINT 2", "(")):
            if (at := text.find(old)) >= 0:
                fix = Fix(f"write {new}", (Edit(Span(at, at + len(old)), new),), safe=True)
                found.append(Diagnostic("W101", Severity.WARNING, Span(at, at + len(old)), old, fixes=(fix,)))
        return tuple(found)

    # the round's text has as many syntax errors as before, one mended and one added: the one added is not kept
    assert fix_text("DIM a\na = ((\nPRINT 2\n", findings, unsafe=False).text == "DIM a\na = 1\nPRINT 2\n"


def test_a_syntax_error_on_a_line_no_fix_changed_is_traced_to_its_fix_by_halving() -> None:
    checks: list[str] = []

    def findings(text: str) -> tuple[Diagnostic, ...]:
        """'x' is fixed as '1', 'y' as 'Y'; a 'Y' anywhere makes the first line a syntax error."""
        checks.append(text)
        found = [Diagnostic("E2003", Severity.ERROR, Span(0, 1), "syntax", mint_error=2003)] if "Y" in text else []
        for at, word in enumerate(text):
            if word in "xy":
                fix = Fix("write", (Edit(Span(at, at + 1), "1" if word == "x" else "Y"),), safe=True)
                found.append(Diagnostic("W101", Severity.WARNING, Span(at, at + 1), word, fixes=(fix,)))
        return tuple(found)

    source = "DIM a\n" + "a = x\n" * 32 + "a = y\n" + "a = x\n" * 32
    assert fix_text(source, findings, unsafe=False).text == source.replace("x", "1")
    assert len(checks) <= 20  # the round, and about two checks a halving (log2 65 < 7) to find the one
