"""A divisor that is zero before the program runs is error 2021, Divide by zero, at the divisor.

The guide's mathematical operators that divide are ``/`` and ``MOD``, also written ``%``
(000:1276-1282, 000:14019-14041). A division by zero is #2021 (000:19063-19070), raised when the
line runs: mint check reports it where the divisor is a number or works out to one from numbers,
constants and macros, and says nothing of a variable, an element or a keyword's reading (``VEL``
may be zero, 000:19066-19070), which only the running program knows. Mint v3's guide lists no such
error (001:12916-13100, 001:13630-13644). Columns are counted by hand from 1.
"""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

import mintlang
from mintlang.runtime.interpreter.vm import StopReason
from tests.analysis.placed import placed_codes
from tests.runtime.running import simulate

_FLAGGED = [
    pytest.param("PRINT 1/0\n", [("E2021", 1, 9)], id="zero"),
    pytest.param("PRINT 1/0.0\n", [("E2021", 1, 9)], id="zero-point-zero"),
    pytest.param("PRINT 1/(0)\n", [("E2021", 1, 9)], id="parenthesised"),
    pytest.param("PRINT 1/-0\n", [("E2021", 1, 9)], id="negated"),
    pytest.param("PRINT 7 MOD 0\n", [("E2021", 1, 13)], id="mod"),
    pytest.param("PRINT 7 % 0\n", [("E2021", 1, 11)], id="percent"),
    pytest.param("PRINT 1/(2-2)\n", [("E2021", 1, 9)], id="difference"),
    pytest.param("PRINT 1/NOT 1\n", [("E2021", 1, 9)], id="not-true"),  # NOT gives 0 or 1 (000:1370)
    pytest.param("PRINT 1/(0/5)\n", [("E2021", 1, 9)], id="quotient-of-zero"),
    pytest.param("PRINT 1/(0/0)\n", [("E2021", 1, 12)], id="only-the-inner-division"),
    pytest.param("DEFINE none = 0\nPRINT 1/none\n", [("E2021", 2, 9)], id="macro"),
    pytest.param("DEFINE bad = 1/0\nPRINT bad\n", [("E2021", 2, 7)], id="division-in-a-macro"),
    pytest.param("DIM a\nIF a = 0 THEN PRINT 1/0\n", [("E2021", 2, 23)], id="then-body"),
    pytest.param("DIM b(2)\nb(1/0) = 1\n", [("E2021", 2, 5)], id="index"),
    pytest.param("PRINT ABS(1/0)\n", [("E2021", 1, 13)], id="argument"),
    # Worked in the controller's binary32 numbers (000:714-716): 0.1 + 0.2 is 0.30000000447 before
    # rounding, nearer 0.3's binary32 value (0.30000001192) than the one below it (0.29999998212).
    pytest.param("PRINT 1/(0.1+0.2-0.3)\n", [("E2021", 1, 9)], id="zero-in-binary32"),
    # 16777217 lies halfway between binary32's 16777216 and 16777218 and rounds to the even one.
    pytest.param("PRINT 1/(16777217-16777216)\n", [("E2021", 1, 9)], id="beyond-the-mantissa"),
]


@pytest.mark.parametrize(("source", "expected"), _FLAGGED)
def test_a_divisor_known_to_be_zero_is_error_2021_at_the_divisor(
    source: str, expected: list[tuple[str, int, int]]
) -> None:
    assert placed_codes(source) == expected


@pytest.mark.parametrize(("source", "expected"), _FLAGGED)
def test_mint_run_stops_with_the_same_error_on_the_same_line(source: str, expected: list[tuple[str, int, int]]) -> None:
    result = simulate(source)
    ((_, line, _),) = expected
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 2021, line)


@pytest.mark.parametrize(
    "source",
    [
        pytest.param("DIM a\nPRINT 1/a\n", id="variable"),
        pytest.param("DIM b(2)\nPRINT 1/b(1)\n", id="element"),
        pytest.param("PRINT 1/VEL.0\n", id="keyword-reading"),
        pytest.param("PRINT 0/1\n", id="zero-dividend"),
        pytest.param("PRINT 1/0.5\n", id="fraction"),
        pytest.param("PRINT 1*0\n", id="product"),
        pytest.param("PRINT 1-0\n", id="difference"),
        pytest.param('PRINT "1/0"\n', id="string"),
        pytest.param("REM 1/0\n", id="comment"),
    ],
)
def test_a_divisor_not_known_to_be_zero_is_not_reported(source: str) -> None:
    assert placed_codes(source) == []


def test_mintmt_raises_it_too() -> None:
    assert placed_codes("PRINT 1/0\n", dialect="mintmt") == [("E2021", 1, 9)]


def test_v3_has_no_divide_by_zero_error() -> None:
    assert "E2021" not in [code for code, _, _ in placed_codes("PRINT 1/0\n", dialect="v3")]


_ZERO = st.recursive(
    st.sampled_from(["0", "0.0", "00"]),
    lambda inner: st.one_of(inner.map(lambda z: f"({z})"), inner.map(lambda z: f"-{z}"), inner.map(lambda z: f"+{z}")),
    max_leaves=6,
)


@given(zero=_ZERO, operator=st.sampled_from(["/", " MOD ", " % "]))
def test_any_bracketing_or_sign_of_zero_is_one_error_at_the_divisor(zero: str, operator: str) -> None:
    assert placed_codes(f"PRINT 5{operator}{zero}\n") == [("E2021", 1, 8 + len(operator))]


@given(divisor=st.integers(min_value=1, max_value=10**6), sign=st.sampled_from(["", "-"]))
def test_a_nonzero_number_is_never_reported(divisor: int, sign: str) -> None:
    assert placed_codes(f"PRINT 5/{sign}{divisor}\n") == []


@pytest.mark.parametrize(
    ("source", "message"),
    [
        pytest.param("PRINT 7 % (1-1)\n", "Divide by zero: 7 % (1-1) divides by zero: (1-1) is always 0", id="folded"),
        pytest.param("PRINT 1/0\n", "Divide by zero: 1/0 divides by zero", id="literal"),
        pytest.param("DEFINE bad = 1/0\nPRINT bad\n", "Divide by zero: bad expands to a division by zero", id="macro"),
    ],
)
def test_the_message_quotes_the_division_as_written(source: str, message: str) -> None:
    (diagnostic,) = mintlang.check(source)
    assert diagnostic.message == message
