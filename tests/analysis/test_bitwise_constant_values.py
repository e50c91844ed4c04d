"""A value built with AND/&, OR/| or XOR is known before the program runs, as one built with +.

The bitwise operators work on the bits of 24-bit values (000:1284-1291, 1338-1340): 5 & 6 is 4
(000:1309-1311) and 01010 XOR 01101 is binary 111 (000:1335-1338). So CAM.0 = _cmCONTINUOUS | 64
is checked against CAM's range like CAM.0 = _cmCONTINUOUS + 64 (error 3, 000:18518).
"""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

import mintlang
from mintlang.semantic.constants import constant_value

_WORD = st.integers(min_value=0, max_value=(1 << 24) - 1)


def _value(expression: str) -> float | None:
    (statement,) = mintlang.parse(f"a = {expression}\n").lines[0].statements
    return constant_value(statement.value)


@pytest.mark.parametrize(
    ("expression", "value"),
    [("5 & 6", 4), ("5 AND 6", 4), ("01010 XOR 01101", 0b111), ("12 | 3", 15), ("12 OR 3", 15)],
)
def test_the_manuals_bitwise_examples_have_their_values(expression: str, value: int) -> None:
    assert _value(expression) == value


@given(_WORD, _WORD)
def test_or_and_xor_of_whole_24_bit_numbers_are_their_bitwise_results(a: int, b: int) -> None:
    assert (_value(f"{a} | {b}"), _value(f"{a} & {b}"), _value(f"{a} XOR {b}")) == (a | b, a & b, a ^ b)


@pytest.mark.parametrize("expression", ["1.5 | 1", "-1 & 3"])
def test_a_fraction_or_a_negative_operand_has_no_known_bitwise_value(expression: str) -> None:
    assert _value(expression) is None


def test_a_bitwise_value_out_of_range_is_error_3_like_a_sum() -> None:
    for source in ("CAM.0 = _cmCONTINUOUS | 64\n", "CAM.0 = _cmCONTINUOUS + 64\n"):
        (diagnostic,) = mintlang.check(source)
        assert (diagnostic.code, "68 is outside" in diagnostic.message) == ("E0003", True)


def test_a_bitwise_value_in_range_is_accepted() -> None:
    assert mintlang.check("CAM.0 = _cmABSOLUTE | _cmCONTINUOUS\n") == []
