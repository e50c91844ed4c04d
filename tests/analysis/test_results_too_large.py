"""A sum, difference, product or quotient of constants too large for a Mint number is error 3 in mint check
and mint-run.

A number has an 8-bit exponent and a 24-bit mantissa (000:714-716), binary32 as simulated, whose largest
value is 340282346638528859811704183484516925440 (2^128 - 2^104, written M below). A result past it has no
value: the run stops with #3, "Data specified out of range" (000:18518-18521), the choice runtime/BEHAVIOUR.md
records as NM-1, and mint check reports the first operation that is too large, at its start. By hand:
16777215^5 is about 1.33e36 and 16777215^6 about 2.23e43; 2^64 * 2^64 is 2^128; M + M and -M - M are
2^129 - 2^105 in size; M / 0.5 is 2M. M + 1 rounds to M (its neighbours are 2^104 apart), 2^64 * 2^63 is
2^127. Columns are counted by hand from 1.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from tests.analysis.placed import placed_codes
from tests.runtime.running import simulate

_M = "340282346638528859811704183484516925440"
_2_64 = "18446744073709551616"
_F = "16777215"

_TOO_LARGE = [
    pytest.param("PRINT " + " * ".join([_F] * 7) + "\n", 7, id="seven times 16777215"),
    pytest.param(f"PRINT {_2_64} * {_2_64}\n", 7, id="2^64 times 2^64"),
    pytest.param(f"PRINT {_M} + {_M}\n", 7, id="the largest number plus itself"),
    pytest.param(f"PRINT -{_M} - {_M}\n", 7, id="too large and negative"),
    pytest.param(f"PRINT {_M} / 0.5\n", 7, id="a quotient"),
    pytest.param(f"PRINT 1 + ({_2_64} * {_2_64})\n", 12, id="in brackets"),
    pytest.param(f"PRINT {_2_64} * {_2_64} * 0\n", 7, id="too large before it is multiplied by 0"),
]


@pytest.mark.parametrize(("source", "column"), _TOO_LARGE)
def test_mint_check_reports_error_3_at_the_first_operation_too_large(source: str, column: int) -> None:
    assert placed_codes(source) == [("E0003", 1, column)]


@pytest.mark.parametrize(("source", "column"), _TOO_LARGE)
def test_mint_run_stops_with_error_3_on_the_same_line(source: str, column: int) -> None:
    result = simulate(source)
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 3, 1)


@pytest.mark.parametrize(
    "source",
    [
        pytest.param("PRINT " + " * ".join([_F] * 5) + "\n", id="five times 16777215"),
        pytest.param(f"PRINT {_2_64} * 9223372036854775808\n", id="2^64 times 2^63"),
        pytest.param(f"PRINT {_M} + 1\nPRINT {_M} * 1\nPRINT {_M} - {_M}\n", id="results a number holds"),
    ],
)
def test_results_a_number_holds_are_not_reported(source: str) -> None:
    assert placed_codes(source) == []
    assert simulate(source).stop.reason is StopReason.END


def test_a_result_with_a_variable_is_known_only_when_the_line_runs() -> None:
    assert placed_codes(f"DIM a = 2\nPRINT a * {_M} * 2\n") == []
