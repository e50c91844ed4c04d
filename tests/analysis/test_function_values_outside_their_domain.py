"""A constant value outside what ACOS, ASIN or LOG are defined for, or an EXP or POW too large for a
number, is error 3 in mint check and mint-run.

ACOS and ASIN take a value "in the range of -1 to 1", LOG one "greater than 0" (000:6279, 000:6595,
000:13723); #3 is "Data specified out of range" (000:18518-18521). Values are worked in the
controller's binary32 numbers (000:714-716): 1.00000001 is held as 1, so ACOS of it is 0 and no
error. The largest of those numbers is (2 - 2^-23) * 2^127, about 3.40282e38: e^89 (about 4.49e38),
10^39 and -2^129 are past it, e^88 (about 1.65e38), 10^38 and 2^127 (about 1.70e38) are not; an EXP
or POW is reported at the call. A variable's value is known only when the line runs. Columns are
counted by hand from 1.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from tests.analysis.placed import placed, placed_codes
from tests.runtime.running import simulate

_OUTSIDE = [
    pytest.param("PRINT ACOS(2)\n", 12, id="ACOS above 1"),
    pytest.param("PRINT ASIN(-1.5)\n", 12, id="ASIN below -1"),
    pytest.param("PRINT LOG(0)\n", 11, id="LOG of 0"),
    pytest.param("PRINT LOG(-3)\n", 11, id="LOG of a negative"),
    pytest.param("PRINT LOG(1-1)\n", 11, id="LOG of a difference that is 0"),
    pytest.param("PRINT LOG 0\n", 11, id="LOG without brackets"),
    pytest.param("PRINT EXP(100)\n", 7, id="EXP of 100"),
    pytest.param("PRINT EXP(89)\n", 7, id="EXP just past the largest number"),
    pytest.param("PRINT POW(10, 39)\n", 7, id="POW of 10 to 39"),
    pytest.param("PRINT POW(10, 400)\n", 7, id="POW too large even for a double"),
    pytest.param("PRINT POW(-2, 129)\n", 7, id="POW too large and negative"),
    pytest.param("PRINT 1 + EXP 100\n", 11, id="EXP without brackets in a sum"),
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
        pytest.param("PRINT EXP(88)\nPRINT POW(10, 38)\nPRINT POW(2, 127)\n", id="results a number holds"),
        pytest.param("DIM a = 2\nPRINT LOG(a)\nPRINT EXP(a * 50)\n", id="a variable"),
    ],
)
def test_values_inside_or_unknown_before_the_run_are_not_reported(source: str) -> None:
    assert placed_codes(source) == []


@pytest.mark.parametrize(
    ("source", "error", "column"),
    [
        pytest.param("PRINT POW(0, -1)\n", 2021, 7, id="0 to a negative power"),
        pytest.param("PRINT POW(-8, 1.5)\n", 3, 7, id="a negative number to a fraction"),
    ],
)
def test_a_pow_without_a_real_value_stops_both_tools_alike(source: str, error: int, column: int) -> None:
    """POW(0, -1) is 1 / 0 (#2021, 000:19063-19070); -8 to the power 1.5 is no real number (#3), the
    choices runtime/BEHAVIOUR.md records as NM-5."""
    assert placed_codes(source) == [(f"E{error:04d}", 1, column)]
    result = simulate(source)
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, error, 1)


def test_a_pow_with_a_real_value_is_not_reported() -> None:
    """0 to the power 0 is 1, and a negative number to a whole power is real: POW(-2, 3) is -8. On MintDrive,
    which takes any index; NextMove's W121 for an index from 0 to 1 is test_pow_index_on_nextmove's."""
    source = "PRINT POW(0, 0)\nPRINT POW(-2, 3)\n"
    assert placed(source, "code", "line", "column", controller="mintdrive") == []
