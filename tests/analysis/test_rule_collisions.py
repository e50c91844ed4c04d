"""The collisions rule (``mintlang/analysis/rules/collisions.py``): the complete list of diagnostics each small
program gets, as (code, severity, line); line numbers in comments refer to the Mint v4 guide (000_*)."""

from __future__ import annotations

from tests.analysis.checking import WARNING, found


def test_two_spellings_of_one_name_are_a_warning_at_the_second() -> None:
    # line 887: only the first ten characters of a name count
    source = "DIM thisIsAVariable1\nthisIsAVaraible2 = 1\nPRINT thisIsAVariable1\n"
    assert found(source) == [("W108", WARNING, 2)]


def test_two_spellings_of_one_label_are_a_warning() -> None:
    assert found("GOSUB thisIsALabel2\nEND\n#thisIsALabel1\nRETURN\n") == [("W108", WARNING, 1)]
