"""A number literal too large for the controller's numbers is error 3, Data specified out of range.

Mint v4 holds every number in an 8-bit exponent and a 24-bit mantissa (000:714-716), binary32 as
simulated, whose largest value is 340282346638528859811704183484516925440 (2^128 - 2^104). A
literal at or past the halfway point to 2^128 (340282356779733661637539395458142568448, which
rounds to the even neighbour, 2^128) has no binary32 value: mint check reports it at the literal
and mint-run stops with error 3 when its line runs. Lines and columns are counted by hand.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from tests.analysis.placed import placed_codes
from tests.runtime.running import simulate

_TOO_LARGE = [
    pytest.param("PRINT 123456789012345678901234567890123456789012345\n", 1, 7, id="45-digits"),
    pytest.param("PRINT 340282356779733661637539395458142568448\n", 1, 7, id="halfway-to-2^128"),
    pytest.param("PRINT 0x100000000000000000000000000000000\n", 1, 7, id="hex-2^128"),
    pytest.param("PRINT 0x" + "F" * 240 + "\n", 1, 7, id="beyond-a-double"),  # 960 bits: no double holds it either
    pytest.param("DIM a(2) = 1, 1" + "0" * 40 + "\nPRINT a(1)\n", 1, 15, id="array-initial-value"),
]


@pytest.mark.parametrize(("source", "line", "column"), _TOO_LARGE)
def test_a_literal_too_large_for_the_controller_is_error_3_at_the_literal(source: str, line: int, column: int) -> None:
    assert placed_codes(source) == [("E0003", line, column)]


@pytest.mark.parametrize(("source", "line", "column"), _TOO_LARGE)
def test_mint_run_stops_with_error_3_on_the_same_line(source: str, line: int, column: int) -> None:
    result = simulate(source)
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 3, line)


@pytest.mark.parametrize(
    "source",
    [
        pytest.param("PRINT 340282346638528859811704183484516925440\n", id="the-largest-binary32"),
        pytest.param("PRINT 0xFFFFFF00000000000000000000000000\n", id="the-largest-in-hex"),
        pytest.param("PRINT 99999999999999999999999999999999999999\n", id="38-digits"),
    ],
)
def test_the_largest_numbers_the_controller_holds_are_not_reported(source: str) -> None:
    assert placed_codes(source) == []
    assert simulate(source).stop.reason is StopReason.END


def test_a_decimal_literal_beyond_a_double_is_error_3_too() -> None:
    """320 digits: past even a double's range, where Python reads it as infinity, which binary32 does not
    refuse; the controller holds it no more than the 45 digits above. The line is also past 255 characters."""
    source = "PRINT " + "1" * 320 + "\n"
    assert placed_codes(source) == [("E0003", 1, 7), ("W111", 1, 256)]
    result = simulate(source)
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 3, 1)
