"""The hints rule (``mintlang/analysis/rules/hints.py``): the complete list of diagnostics each small
program gets, as (code, severity, line); line numbers in comments refer to the Mint v4 guide (000_*)."""

from __future__ import annotations

import mintlang
from mintlang import Diagnostic
from tests.analysis.checking import INFO, apply, found


def hints(source: str) -> list[Diagnostic]:
    """The hints of a program, which are reported only when asked for."""
    return list(mintlang.check_application(source, select=("I",)).program)


def test_hints_are_reported_only_when_selected() -> None:
    assert found("DIM b\nb = POS[1]\n") == []
    assert [d.code for d in hints("DIM b\nb = POS[1]\n")] == ["I201"]


def test_one_axis_in_brackets_gets_a_hint_to_use_the_dot() -> None:
    # lines 682-688: b = POS.1 is smaller and faster than b = POS[1]
    source = "DIM b\nb = POS[1]\n"
    (hint,) = hints(source)
    assert (hint.code, hint.severity.value, source[hint.span.start : hint.span.end]) == ("I201", INFO, "[1]")
    (fix,) = hint.fixes
    fixed = apply(source, fix.edits)
    assert fixed == "DIM b\nb = POS.1\n"
    assert hints(fixed) == []


def test_the_dot_hint_keeps_a_macro_with_the_delimiter_it_needs() -> None:
    # lines 1508-1516: MOVER..xAxis, since a dot before a macro is ignored
    source = "DEFINE xAxis = 0\nMOVER[xAxis] = 10\n"
    (hint,) = hints(source)
    (fix,) = hint.fixes
    assert apply(source, fix.edits) == "DEFINE xAxis = 0\nMOVER..xAxis = 10\n"
    assert hints(apply(source, fix.edits)) == []


def test_several_axes_in_brackets_get_no_hint() -> None:
    assert found("PAUSE IDLE[0,1]\n") == []
