"""Applying fixes (``mintlang.fixes``): which fixes apply, overlapping ones, rounds until nothing more applies."""

from __future__ import annotations

from collections import Counter

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mintlang import check, check_application
from mintlang.diagnostics import Diagnostic, Edit, Fix, Severity, Span, with_edits
from mintlang.fixes import MAX_ROUNDS, apply_once, automatic_fix, fix_text
from tests.corpus_files import FRAGMENT_ALLOWANCE, CorpusCase, cases
from tests.fuzzing import examples


def finding(start: int, end: int, *fixes: Fix) -> Diagnostic:
    return Diagnostic("W101", Severity.WARNING, Span(start, end), "test", fixes=fixes)


def replacing(start: int, end: int, text: str, *, safe: bool) -> Fix:
    return Fix(f"write {text}", (Edit(Span(start, end), text),), safe=safe)


def test_a_safe_fix_applies_and_an_unsafe_one_only_when_asked() -> None:
    safe, unsafe = replacing(0, 1, "A", safe=True), replacing(0, 1, "A", safe=False)
    assert automatic_fix(finding(0, 1, safe), unsafe=False) is safe
    assert automatic_fix(finding(0, 1, unsafe), unsafe=False) is None
    assert automatic_fix(finding(0, 1, unsafe), unsafe=True) is unsafe


def test_a_finding_offered_several_fixes_is_left_to_its_author() -> None:
    choices = finding(0, 1, replacing(0, 1, "A", safe=True), replacing(0, 1, "B", safe=True))
    assert automatic_fix(choices, unsafe=True) is None


def test_fixes_that_do_not_overlap_apply_together() -> None:
    text, fixed = apply_once(
        "ab cd",
        [finding(3, 5, replacing(3, 5, "CD", safe=True)), finding(0, 2, replacing(0, 2, "AB", safe=True))],
        unsafe=False,
    )
    assert text == "AB CD"
    assert [d.span for d in fixed] == [Span(0, 2), Span(3, 5)]


def test_of_two_overlapping_fixes_the_first_in_the_text_applies() -> None:
    first, second = finding(0, 3, replacing(0, 3, "X", safe=True)), finding(2, 4, replacing(2, 4, "Y", safe=True))
    assert apply_once("abcd", [second, first], unsafe=False) == ("Xd", [first])


def test_one_insertion_two_findings_ask_for_is_made_once() -> None:
    one, two = (
        finding(0, 1, replacing(0, 0, "DIM a\n", safe=True)),
        finding(6, 7, replacing(0, 0, "DIM a\n", safe=True)),
    )
    assert apply_once("a = 1\na = 2\n", [one, two], unsafe=False)[0] == "DIM a\na = 1\na = 2\n"


def test_different_insertions_at_one_place_are_made_in_the_order_of_their_findings() -> None:
    first, second = (
        finding(6, 7, replacing(0, 0, "DIM a\n", safe=True)),
        finding(8, 9, replacing(0, 0, "DIM b\n", safe=True)),
    )
    assert apply_once("PRINT a, b\n", [second, first], unsafe=False)[0] == "DIM a\nDIM b\nPRINT a, b\n"


def test_an_insertion_goes_before_a_replacement_that_starts_at_its_place() -> None:
    """A DIM above the first statement and that statement's own fix, in one round: the DIM is inserted before
    the replaced text, which is replaced whole (#FASTPOS, Mint v3's, is v4's #FASTIN; 'a' is declared)."""
    insertion, replacement = Edit(Span(0, 0), "DIM a\n"), Edit(Span(0, 8), "#FASTIN")
    assert with_edits("#FASTPOS\na = 1\n", [replacement, insertion]) == "DIM a\n#FASTIN\na = 1\n"
    assert with_edits("#FASTPOS\na = 1\n", [insertion, replacement]) == "DIM a\n#FASTIN\na = 1\n"
    assert fix_text("#FASTPOS\na = 1\n", check, unsafe=True).text == "DIM a\n#FASTIN\na = 1\n"


def test_a_fix_that_leaves_its_finding_is_undone() -> None:
    """A declaration the checker still reports undeclared is not written at all, rather than once a round."""

    def unmoved(text: str) -> tuple[Diagnostic, ...]:
        return (finding(0, 1, replacing(0, 0, "DIM a\n", safe=True)),)

    result = fix_text("a = 1\n", unmoved, unsafe=False)
    assert (result.text, result.fixed, result.converged) == ("a = 1\n", (), True)


def test_a_fix_set_aside_is_tried_again_once_the_text_has_moved_on() -> None:
    """END SUB becomes RETURN (000:1841-1850) in the round that removes the line a GOTO leaves unreachable; the
    GOTO after the new RETURN is then unreachable too, and the finding, now spanning both lines, starts before
    the one fixed: the round is undone, and the removal set aside. Once the text has moved on (RETURN written,
    the label and the DIM added), the removal is tried again, so a second --fix finds nothing more."""
    once = fix_text("END SUB\nGOTO done\na = 1\n", check, unsafe=True)
    assert (once.text, once.converged) == ("DIM a\nRETURN\n\n#done\n", True)


def test_a_finding_a_round_reveals_like_the_one_it_fixed_is_fixed_in_the_same_run() -> None:
    """END SUB becomes RETURN (000:1841-1850) in the round that removes the line END leaves unreachable; the
    line after the new RETURN is then unreachable too, a finding like the one fixed, and the removal was set
    aside for good: a second --fix removed both lines. The new one is further on, so it is not taken for the
    fixed one left in place."""
    source = "GOSUB s\nEND\nPRINT 1\n#s\nEND SUB\nPRINT 2\n"
    once = fix_text(source, check, unsafe=True)
    assert (once.text, once.converged) == ("GOSUB s\nEND\n#s\nRETURN\n", True)
    assert fix_text(once.text, check, unsafe=True).text == once.text


@pytest.mark.parametrize(
    ("source", "after"),
    [
        # the parse stops at the first &HFF (000:769-770): the second is reported only once the first is mended,
        # with the same message, a new finding further on, not the one fixed still there
        pytest.param("PRINT &HFF, &HFF\n", "PRINT 0xFF, 0xFF\n", id="two-hex-literals"),
        pytest.param("DIM a\nDIM b\na = b ^ 2 + b ^ 2\n", "DIM a\nDIM b\na = POW(b, 2) + POW(b, 2)\n", id="two-powers"),
    ],
)
def test_a_finding_like_the_one_fixed_further_on_is_fixed_too(source: str, after: str) -> None:
    result = fix_text(source, check, unsafe=False)
    assert (result.text, result.converged) == (after, True)


def test_fixing_goes_on_until_the_text_has_nothing_more_to_fix() -> None:
    """IDL is respelt IDLE (unsafe: a guess); the next round turns IDLE[0] into IDLE.0 (the hint's safe fix)."""
    source = "PAUSE IDL[0]\n"

    def findings(text: str) -> tuple[Diagnostic, ...]:
        return check_application(text, select=("E", "W", "I")).program

    result = fix_text(source, findings, unsafe=True)
    assert result.text == "PAUSE IDLE.0\n"
    assert [d.code for d in result.fixed] == ["E3007", "I201"]
    assert result.remaining == () and result.converged


def test_rounds_are_bounded_when_fixes_never_settle() -> None:
    def always_one_more(text: str) -> tuple[Diagnostic, ...]:
        growing = Diagnostic(
            "W101", Severity.WARNING, Span(0, 0), f"{len(text)} long", fixes=(replacing(0, 0, "x", safe=True),)
        )
        return (growing,)

    result = fix_text("", always_one_more, unsafe=False)
    assert result.text == "x" * MAX_ROUNDS
    assert not result.converged


@pytest.mark.parametrize(
    ("source", "after"),
    [
        pytest.param("PRINT “hello”\n", 'PRINT "hello"\n', id="W101-plain-quotes"),
        pytest.param("PRINT 1 : REM mint: ignore[W103]\n", "PRINT 1\n", id="W117-unused-suppression"),
    ],
)
def test_safe_fixes_of_the_checker(source: str, after: str) -> None:
    assert fix_text(source, check, unsafe=False).text == after


@pytest.mark.parametrize(
    "source",
    [
        pytest.param("count = 1\nPRINT count\n", id="E3001-declare"),
        pytest.param("PAUSE IDL[0]\n", id="E3007-respell"),
        pytest.param("HMSPEED = 2\n", id="E3007-v3-rename"),
        pytest.param("END\nPRINT 1\n", id="W106-remove-unreachable"),
        pytest.param("GOSUB FASTPOS\nEND\n#FASTPOS\nRETURN\n", id="W102-v3-label-called-by-name"),
    ],
)
def test_unsafe_fixes_are_not_applied_by_default(source: str) -> None:
    assert any(fix.safe is False for d in check(source) for fix in d.fixes)  # offered, and unsafe
    assert fix_text(source, check, unsafe=False).text == source


CORPUS = [case for folder in ("v4/valid", "v4/invalid", "v4/runtime", "v3/programs") for case in cases(folder)]


@pytest.mark.parametrize("unsafe", [False, True], ids=["safe", "unsafe"])
def test_on_the_corpus_fixing_twice_is_fixing_once_and_safe_fixes_add_no_error(unsafe: bool) -> None:
    """Invariants over every corpus program: what --fix leaves has nothing more it would fix, and
    the safe fixes never make an error appear (the unsafe ones may: they guess)."""
    for case in CORPUS:

        def findings(text: str, case: CorpusCase = case) -> tuple[Diagnostic, ...]:
            options = {"controller": case.controller, "dialect": case.dialect, "config": case.configuration}
            return check_application(text, select=("E", "W", "I"), **options).program  # type: ignore[arg-type]

        once = fix_text(case.source, findings, unsafe=unsafe)
        assert once.converged, case.name
        assert fix_text(once.text, findings, unsafe=unsafe).text == once.text, case.name
        if not unsafe:  # a fragment's undeclared names show once its syntax error is mended
            allowed = FRAGMENT_ALLOWANCE if case.fragment else frozenset()
            before = Counter(d.code for d in findings(case.source) if d.severity is Severity.ERROR)
            after = Counter(d.code for d in once.remaining if d.severity is Severity.ERROR and d.code not in allowed)
            assert after <= before, case.name


# Lines a newcomer writes, each offered a fix or making another's: other BASICs' habits, v3 words, typos.
WRITTEN = [
    "a = 1", "PRINT a", "GOSUB init", "GOTO done", "END", "PRINT “x”", "IF a THEN", "ENDIF", "#init", "RETURN",
    "PRINT 1 : REM mint: ignore[W103]", "PAUSE idl[0]", "count++", "// note", "LET b = 2", "PRINT POS[1]", "ELSE",
    "loop", "endl", "prnt a", "DIM a", "b += 2", "PRINT a ^ 2", "CALL init", "END SUB", "DELAY 10", "#FASTPOS",
    "HMSPEED = 2", "WHILE a", "ENDW", "PRINT \"a\" + b", "a = a + 1 // more", "",
]  # fmt: skip


@settings(max_examples=examples(150))
@given(st.lists(st.sampled_from(WRITTEN), min_size=1, max_size=10), st.booleans())
def test_fixing_twice_is_fixing_once(lines: list[str], unsafe: bool) -> None:
    once = fix_text("\n".join(lines) + "\n", check, unsafe=unsafe)
    assert once.converged
    assert fix_text(once.text, check, unsafe=unsafe).text == once.text
