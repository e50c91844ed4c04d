"""Printed numbers, checked against the manual's worked examples (spec PR-1..PR-3)."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from mintlang.runtime.numbers import BINARY_OPERATORS, FUNCTIONS, UNARY_OPERATORS, f32
from mintlang.runtime.printing import format_bin, format_chr, format_hex, format_number, format_using

# PR-1: four places, truncated


@pytest.mark.parametrize(
    ("value", "printed"),
    [
        (1.005103, "1.0051"),
        (27, "27"),
        (45, "45"),
        (-35, "-35"),
        (0.5, "0.5"),
        (16777215, "16777215"),
    ],
)
def test_plain_numbers_print_up_to_four_places_without_trailing_zeros(value: float, printed: str) -> None:
    assert format_number(f32(value)) == printed


@pytest.mark.parametrize(("whole", "printed"), [(1, "1.555"), (8388600, "8388600.5")])
def test_sums_print_the_binary32_result(whole: float, printed: str) -> None:
    assert format_number(BINARY_OPERATORS["+"](whole, f32(0.555))) == printed


def test_a_decimal_stored_just_below_itself_prints_one_ten_thousandth_low() -> None:
    assert format_number(f32(0.7)) == "0.6999"
    assert format_number(f32(2.3)) == "2.2999"


def test_cos_45_prints_0_7071() -> None:
    assert format_number(FUNCTIONS["COS"](45)) == "0.7071"


def test_fractions_are_truncated_not_rounded() -> None:
    assert format_number(f32(5.710593)) == "5.7105"
    assert format_number(f32(0.99999)) == "0.9999"
    assert format_number(f32(-2.71828)) == "-2.7182"


def test_negative_zero_and_tiny_negatives_print_zero() -> None:
    assert format_number(-0.0) == "0"
    assert format_number(f32(-0.00001)) == "0"


def test_the_largest_binary32_prints_every_integer_digit() -> None:
    assert format_number(f32(3.4028234663852886e38)) == "340282346638528859811704183484516925440"


@given(st.floats(width=32, allow_nan=False, allow_infinity=False))
def test_format_number_never_raises(x: float) -> None:
    assert format_number(x)


@given(st.floats(min_value=-8388607, max_value=8388607, width=32))
def test_format_number_reads_back_within_a_ten_thousandth(x: float) -> None:
    assert abs(float(format_number(x)) - x) < 0.0001


# PR-2: USING


@pytest.mark.parametrize(
    ("value", "integer_digits", "fraction_digits", "printed"),
    [
        (-123.5, -5, 1, "-00123.5"),
        (123.5, 4, None, "0123"),
        (123.5, 5, 2, "00123.50"),
        (1.005103, 1, 6, "1.005102"),
        (123.5, -5, 1, "+00123.5"),
    ],
)
def test_using_pads_and_truncates(value: float, integer_digits: int, fraction_digits: int | None, printed: str) -> None:
    assert format_using(f32(value), integer_digits, fraction_digits) == printed


def test_using_widens_the_integer_part_when_it_needs_more_digits() -> None:
    assert format_using(123456.0, 2, None) == "123456"


def test_using_a_positive_width_prints_no_sign() -> None:
    assert format_using(-123.5, 5, 1) == "00123.5"


def test_using_truncates_the_fraction() -> None:
    assert format_using(f32(2.999), 1, 2) == "2.99"


def test_using_zero_fraction_digits_prints_no_point() -> None:
    assert format_using(7.9, 2, 0) == "07"


def test_using_digit_counts_are_limited_to_fifteen() -> None:
    assert format_using(1.5, 20, 20) == "0" * 14 + "1.5" + "0" * 14


def test_using_never_prints_a_negative_zero() -> None:
    assert format_using(-0.001, -2, 1) == "+00.0"


# PR-3: HEX and BIN


@pytest.mark.parametrize(
    ("value", "printed"),
    [(27, "11011"), (0x1A, "11010"), (0, "0"), (UNARY_OPERATORS["~"](0b01100101), "111111111111111110011010")],
)
def test_bin_prints_binary_digits_without_leading_zeros(value: float, printed: str) -> None:
    assert format_bin(value) == printed


@pytest.mark.parametrize(
    ("value", "printed"),
    [(74, "4A"), (255, "FF"), (0x5A31C, "5A31C"), (UNARY_OPERATORS["~"](2), "FFFFFD"), (-1, "FFFFFF")],
)
def test_hex_prints_upper_case_without_prefix(value: float, printed: str) -> None:
    assert format_hex(value) == printed


def test_chr_prints_the_character_of_its_code() -> None:
    assert format_chr(65) == "A"
    assert format_chr(7) == "\a"
    assert format_chr(256 + 13) == "\r"
