"""A constant value outside what ACOS, ASIN or LOG are defined for is error 3 in mint check and mint-run.

ACOS and ASIN take a value "in the range of -1 to 1", LOG one "greater than 0" (000:6279, 000:6595,
000:13723); #3 is "Data specified out of range" (000:18518-18521). Values are worked in the
controller's binary32 numbers (000:714-716): 1.00000001 is held as 1, so ACOS of it is 0 and no
error. A variable's value is known only when the line runs. Columns are counted by hand from 1.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from tests.analysis.placed import placed_codes
from tests.runtime.running import simulate

_OUTSIDE = [
    pytest.param("PRINT ACOS(2)\n", 12, id="ACOS above 1"),
    pytest.param("PRINT ASIN(-1.5)\n", 12, id="ASIN below -1"),
    pytest.param("PRINT LOG(0)\n", 11, id="LOG of 0"),
    pytest.param("PRINT LOG(-3)\n", 11, id="LOG of a negative"),
    pytest.param("PRINT LOG(1-1)\n", 11, id="LOG of a difference that is 0"),
    pytest.param("PRINT LOG 0\n", 11, id="LOG without brackets"),
]


@pytest.mark.parametrize(("source", "column"), _OUTSIDE)
def test_mint_check_reports_error_3_at_the_value(source: str, column: int) -> None:
    assert placed_codes(source) == [("E0003", 1, column)]


@pytest.mark.parametrize(("source", "column"), _OUTSIDE)
def test_mint_run_stops_with_error_3_on_the_same_line(source: str, column: int) -> None:
    result = simulate(source)
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 3, 1)


@pytest.mark.parametrize(
    "source",
    [
        pytest.param("PRINT ACOS(1)\nPRINT ASIN(-1)\n", id="the ends of -1 to 1"),
        pytest.param("PRINT ACOS(1.00000001)\n", id="held as 1 in binary32"),
        pytest.param("DIM a = 2\nPRINT LOG(a)\n", id="a variable"),
    ],
)
def test_values_inside_or_unknown_before_the_run_are_not_reported(source: str) -> None:
    assert placed_codes(source) == []
