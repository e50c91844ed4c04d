"""The arrays rule (``mintlang/analysis/rules/arrays.py``): the complete list of diagnostics each small
program gets, as (code, severity, line); line numbers in comments refer to the Mint v4 guide (000_*)."""

from __future__ import annotations

from tests.analysis.checking import ERROR, found, only


def test_an_arrays_size_and_values_are_numbers_not_expressions() -> None:
    # 000:9171: <no_of_elements> and <array values> are Mint numbers and not expressions
    source = "DIM n = 5\nDIM a(n)\nDIM b(2*5)\nDIM c(2) = n, 2\nPRINT n, a(1), b(1), c(1)\n"
    assert found(source) == [("E2003", ERROR, 2), ("E2003", ERROR, 3), ("E2003", ERROR, 4)]
    numbers = "DIM e(4) = -1, 0x10, 'A', _TRUE\nPRINT e(1)\n"
    assert found(numbers) == []


def test_an_array_the_compiler_cannot_make_is_error_2016_at_its_dim() -> None:
    # 000:9171 and 19038: an array has <no_of_elements> elements, indexed 1 to that number, so a size that
    # is no whole number from 1 is no array, and a value beyond the size would have no index; its uses
    # are not reported again
    source = "DIM a(0)\nDIM b(2.5)\nDIM c(3) = 1, 2, 3, 4\nDIM d(3) = 1, 2, 3\nDIM e(3) = 1;\n"
    source += "PRINT a(1), b(1), c(1), d(3), e(3)\n"
    assert found(source) == [("E2016", ERROR, 1), ("E2016", ERROR, 2), ("E2016", ERROR, 3)]
    extra = only("DIM c(3) = 1, 2, 3, 4\nPRINT c(1)\n", "E2016")
    assert (extra.span.start, extra.message.endswith("c has 3 elements: 4 values are too many")) == (20, True)


def test_a_constant_index_outside_the_array_is_error_2016() -> None:
    # line 19038: indices are in the range 1 <= index <= size
    source = "DIM a(10)\na(0) = 1\na(11) = 2\na(10) = 3\na(1) = 4\nPRINT a(12)\n"
    assert found(source) == [("E2016", ERROR, 2), ("E2016", ERROR, 3), ("E2016", ERROR, 6)]


def test_a_constant_fractional_index_is_judged_as_the_run_takes_it() -> None:
    # the guide does not say what a fractional index does (000:1063-1066, 19038-19046); mint-run cuts it to its
    # whole part (runtime/BEHAVIOUR.md), so a(0.5) is a(0), outside 1 to 3, and a(3.5) is a(3)
    source = "DIM a(3)\nPRINT a(0.5)\nPRINT a(3.5)\nPRINT a(-0.5)\nPRINT a(4.2)\n"
    assert found(source) == [("E2016", ERROR, 2), ("E2016", ERROR, 4), ("E2016", ERROR, 5)]
    assert only("DIM a(3)\nPRINT a(0.5)\n", "E2016").message.endswith(
        "a(0.5) is outside 1 to 3: a fractional index is cut to its whole part, 0"
    )


def test_an_element_of_a_plain_variable_is_error_2016() -> None:
    # 3.3: an array is declared with its size, DIM name(n); a plain variable has no elements
    assert found("DIM y\ny(2) = 1\n") == [("E2016", ERROR, 2)]


def test_the_manuals_invalid_index_example() -> None:
    # line 19041
    source = "DIM axis_speeds(100)\naxis_speeds(0) = 1000\naxis_speeds(101) = 2000\n"
    assert found(source) == [("E2016", ERROR, 2), ("E2016", ERROR, 3)]
