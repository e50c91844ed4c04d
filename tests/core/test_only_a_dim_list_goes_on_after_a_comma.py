"""A trailing comma carries a DIM's values on to the next line (000:1093-1095); a PRINT's trailing comma only
keeps the cursor on the terminal line (000:15297-15300), and the next physical line is a statement of its own,
even when a DIM stands earlier on the line."""

from __future__ import annotations

import pytest

import mintlang
from mintlang.runtime.run import run_source


@pytest.mark.parametrize(
    ("source", "first_lines"),
    [
        ("DIM a : PRINT a,\nPRINT 2\n", [1, 2]),
        ("DIM t(2) = 1, 2 : PRINT t(1),\nPRINT t(2)\n", [1, 2]),
        ("DIM t(3) = 1,\n 2, 3 : PRINT t(1),\nPRINT t(3)\n", [1, 3]),  # lines 1-2 are one DIM list
    ],
)
def test_a_print_ending_in_a_comma_after_a_dim_leaves_the_next_line_alone(source: str, first_lines: list[int]) -> None:
    assert [line.number for line in mintlang.parse(source).placed] == first_lines
    assert mintlang.check(source) == []


def test_the_next_line_prints_straight_after() -> None:
    # PRINT a, leaves the cursor after the 0 of a; the next PRINT goes on from there
    assert run_source("DIM a : PRINT a,\nPRINT 2\n").terminal == "02\n"


@pytest.mark.parametrize(
    ("source", "values"),
    [
        ("DIM t(4) = 1, 2,\n  3, 4\nPRINT t(4)\n", "4"),
        ("PRINT 0 : DIM t(3) = 1,\n 2,\n 3\nPRINT t(3)\n", "0\n3"),
    ],
)
def test_a_dim_list_still_goes_on(source: str, values: str) -> None:
    assert mintlang.check(source) == []
    assert run_source(source).terminal == values + "\n"
