"""PRINT and LINE print at most 15 digits either side of the point with USING, INPUT accepts at
most 15 integer and 3 fractional digits (W118).

PRINT's entry caps both ``<int>`` and ``<frac>`` at 15 and prints a sign for a negative
``<int>`` (000:15313-15318); LINE formats its values as PRINT does (000:13657-13660). INPUT's
entry limits ``<int>`` to 15 characters without the sign and ``<frac>`` to 3 (the table of keys
under "INPUT", 000:12247-12249). The guide numbers no error for more, so the toolchain warns.
"""

from __future__ import annotations

import pytest

import mintlang


def _codes(source: str) -> list[str]:
    return [d.code for d in mintlang.check(source)]


@pytest.mark.parametrize(
    "statement",
    [
        "PRINT a USING 15",
        "PRINT a USING -15, 15",
        "PRINT a USING 5, 2",
        'LINE #3 2, "A = ", a USING 15, 15',
        "INPUT a USING 15",
        'INPUT "A = ", a USING -15, 3',
    ],
)
def test_digits_within_the_limits_pass(statement: str) -> None:
    assert _codes(f"DIM a = 123.5\n{statement}\n") == []


@pytest.mark.parametrize(
    "statement",
    [
        "PRINT a USING 16",
        "PRINT a USING -16, 2",
        "PRINT a USING 5, 16",
        'LINE #3 2, "A = ", a USING 16, 2',
        "IF a > 1 THEN PRINT a USING 20",
        "INPUT a USING 16",
        'INPUT "A = ", a USING -5, 4',
    ],
)
def test_more_digits_than_the_statement_takes_is_w118(statement: str) -> None:
    assert _codes(f"DIM a = 123.5\n{statement}\n") == ["W118"]


def test_both_counts_too_large_give_one_warning_each() -> None:
    assert _codes("DIM a = 123.5\nPRINT a USING 16, 16\n") == ["W118", "W118"]
