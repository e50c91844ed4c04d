"""The numeric model, checked against the manual's worked examples (spec NM-1, NM-3, NM-5)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from mintlang.runtime.errors import MintError
from mintlang.runtime.numbers import (
    BINARY_OPERATORS,
    FUNCTIONS,
    MASK24,
    UNARY_OPERATORS,
    bits24,
    f32,
)
from mintlang.runtime.printing import format_number

finite_f32 = st.floats(width=32, allow_nan=False, allow_infinity=False)


def op(symbol: str, a: float, b: float) -> float:
    return BINARY_OPERATORS[symbol](f32(a), f32(b))


def call(name: str, *arguments: float) -> float:
    return FUNCTIONS[name](*(f32(argument) for argument in arguments))


# NM-1: binary32 storage and arithmetic


def test_integers_are_exact_up_to_16777215() -> None:
    assert f32(16777215) == 16777215
    assert op("+", 16777214, 1) == 16777215
    assert op("-", -16777214, 1) == -16777215


def test_integers_beyond_24_bits_lose_accuracy() -> None:
    assert f32(16777217) == 16777216


def test_fraction_precision_falls_as_the_integer_part_grows() -> None:
    assert format_number(op("+", 1, 0.555)) == "1.555"
    assert format_number(op("+", 8388600, 0.555)) == "8388600.5"


def test_f32_rounds_to_nearest_even() -> None:
    assert f32(1 + 2**-24) == 1.0
    assert f32(1 + 3 * 2**-24) == 1 + 2**-22


def test_a_result_too_large_for_binary32_is_out_of_range() -> None:
    with pytest.raises(MintError) as raised:
        op("*", 3e38, 10)
    assert raised.value.code == 3


@given(finite_f32)
def test_f32_leaves_binary32_values_unchanged(x: float) -> None:
    assert f32(x) == x


# NM-3: operators


def test_relational_operators_return_one_or_zero() -> None:
    assert [op(symbol, 2, 3) for symbol in ("=", "<>", "<", ">", "<=", ">=")] == [0, 1, 1, 0, 1, 0]
    assert op("=", 5, 5) == 1.0


def test_twelve_mod_five_is_two() -> None:
    assert op("MOD", 12, 5) == 2
    assert op("%", 12, 5) == 2


def test_mod_follows_c_fmod_sign_of_the_dividend_and_keeps_fractions() -> None:
    assert op("MOD", -7, 3) == -1
    assert op("MOD", 7, -3) == 1
    assert op("MOD", 5.5, 2) == 1.5


@pytest.mark.parametrize("symbol", ["/", "MOD", "%"])
def test_dividing_by_zero_is_error_2021(symbol: str) -> None:
    with pytest.raises(MintError) as raised:
        op(symbol, 1, 0)
    assert raised.value.code == 2021


def test_division_rounds_to_binary32() -> None:
    assert op("/", 10, 45) == f32(10 / 45)


def test_five_and_six_is_four() -> None:
    assert op("&", 5, 6) == 4
    assert op("AND", 5, 6) == 4


def test_or_and_xor_work_on_bits() -> None:
    assert op("|", 5, 6) == 7
    assert op("OR", 5, 6) == 7
    assert op("XOR", 5, 6) == 3


def test_complement_is_unsigned_24_bit() -> None:
    assert UNARY_OPERATORS["~"](2) == 16777213
    assert UNARY_OPERATORS["~"](0b1100101) == 0b111111111111111110011010


def test_bitwise_operands_are_truncated_toward_zero() -> None:
    assert op("&", 7.9, 3.2) == 3
    assert bits24(-1.5) == MASK24


def test_bit_23_is_usable_in_a_bitmap() -> None:
    assert op("|", 2**23, 1) == 2**23 + 1


def test_not_returns_one_for_zero_and_zero_otherwise() -> None:
    assert UNARY_OPERATORS["NOT"](0) == 1
    assert UNARY_OPERATORS["!"](-3.5) == 0


def test_unary_minus_and_plus() -> None:
    assert UNARY_OPERATORS["-"](5) == -5
    assert UNARY_OPERATORS["+"](0.1) == f32(0.1)


@given(st.floats(min_value=-1e30, max_value=1e30, allow_nan=False))
def test_bits24_is_always_an_unsigned_24_bit_value(x: float) -> None:
    assert 0 <= bits24(x) <= 16777215


@given(st.integers(min_value=-(2**24), max_value=2**24 - 1))
def test_bits24_is_twos_complement_for_whole_numbers(n: int) -> None:
    assert bits24(n) == n % 2**24


@given(finite_f32, finite_f32)
def test_bitwise_results_are_unsigned_24_bit(a: float, b: float) -> None:
    for symbol in ("&", "|", "XOR"):
        assert 0 <= op(symbol, a, b) <= 16777215


# NM-5: functions


def test_cos_45_prints_0_7071() -> None:
    assert format_number(call("COS", 45)) == "0.7071"


def test_trigonometry_works_in_degrees() -> None:
    assert call("SIN", 90) == 1
    assert call("SIN", 30) == 0.5
    assert call("TAN", 45) == pytest.approx(1)


def test_asin_of_0_707107_prints_45() -> None:
    assert format_number(call("ASIN", 0.707107)) == "45"


def test_atan_0_1_prints_5_7105() -> None:
    assert format_number(call("ATAN", 0.1)) == "5.7105"


def test_acos_of_10_over_45_prints_77_1604() -> None:
    assert format_number(call("ACOS", op("/", 10, 45))) == "77.1604"


def test_acos_ranges_over_0_to_180_degrees() -> None:
    assert call("ACOS", -1) == 180
    assert call("ACOS", 1) == 0


@pytest.mark.parametrize("name", ["ASIN", "ACOS"])
def test_inverse_sine_and_cosine_outside_minus_one_to_one_are_out_of_range(name: str) -> None:
    with pytest.raises(MintError) as raised:
        call(name, 1.5)
    assert raised.value.code == 3


def test_sqrt_of_a_negative_number_is_zero() -> None:
    assert call("SQRT", -4) == 0
    assert call("SQRT", 16) == 4


def test_log_2_prints_0_6931() -> None:
    assert format_number(call("LOG", 2)) == "0.6931"


@pytest.mark.parametrize("argument", [0, -1])
def test_log_of_a_number_that_is_not_positive_is_out_of_range(argument: float) -> None:
    with pytest.raises(MintError) as raised:
        call("LOG", argument)
    assert raised.value.code == 3


def test_exp_of_3_over_20_prints_1_1618() -> None:
    assert format_number(call("EXP", op("/", 3, 20))) == "1.1618"


def test_exp_too_large_is_out_of_range() -> None:
    with pytest.raises(MintError) as raised:
        call("EXP", 100)
    assert raised.value.code == 3


def test_pow_2_3_is_8() -> None:
    assert call("POW", 2, 3) == 8


def test_pow_has_no_exponent_restriction() -> None:
    assert call("POW", 9, 0.5) == 3
    assert call("POW", 5, 1) == 5


def test_pow_without_a_real_result_is_an_error() -> None:
    with pytest.raises(MintError) as negative_base:
        call("POW", -8, 0.5)
    with pytest.raises(MintError) as zero_base:
        call("POW", 0, -1)
    assert (negative_base.value.code, zero_base.value.code) == (3, 2021)


def test_int_of_12_4_plus_3_2_is_15() -> None:
    assert call("INT", op("+", 12.4, 3.2)) == 15


def test_int_truncates_toward_zero() -> None:
    assert call("INT", -2.5) == -2


def test_abs_of_7_times_minus_5_is_35() -> None:
    assert call("ABS", op("*", 7, -5)) == 35


def test_chr_as_an_expression_is_its_code() -> None:
    assert call("CHR", 65) == 65


@given(st.sampled_from(sorted(set(FUNCTIONS) - {"POW"})), finite_f32)
def test_functions_return_binary32_values_or_a_mint_error(name: str, x: float) -> None:
    try:
        result = call(name, x)
    except MintError as error:
        assert error.code in {3, 2021}
    else:
        assert math.isfinite(result)
        assert f32(result) == result
