"""An array indexed in square brackets (``arr[2] = 3``) is error 3007 only, not also an unused variable.

"The index is always enclosed in round brackets to distinguish it from a
reference to axis numbers which are in square brackets" (000:1063-1066): Mint
reads ``arr[2]`` as a keyword with an axis list, and has no keyword ARR. A user
coming from C writes it so; the name is theirs and used, if wrongly, so W103
("declared but never used") would send them looking for the wrong mistake.
"""

from __future__ import annotations

import pytest

import mintlang


def _found(source: str) -> list[tuple[str, int, int]]:
    """(code, line, column) of each finding, in position order."""
    document = mintlang.parse(source)
    return [
        (d.code, document.line_index.position(d.span.start).line, document.line_index.position(d.span.start).column)
        for d in mintlang.check(source)
    ]


@pytest.mark.parametrize(
    ("source", "column"),
    [("DIM arr(5)\narr[2] = 3\n", 1), ("DIM arr(5)\nPRINT arr[2]\n", 7), ("DIM speeds(3)\nSPEED = speeds[1]\n", 9)],
)
def test_square_brackets_on_an_array_are_one_error_3007(source: str, column: int) -> None:
    assert _found(source) == [("E3007", 2, column)]


def test_the_array_counts_as_used_and_an_untouched_variable_is_still_unused() -> None:
    assert _found("DIM arr(5)\nDIM spare\narr[2] = 3\n") == [("W103", 2, 5), ("E3007", 3, 1)]


def test_round_brackets_index_the_array() -> None:
    assert _found("DIM arr(5)\narr(2) = 3\nPRINT arr(2)\n") == []


def _error_3007(source: str) -> mintlang.Diagnostic:
    (error,) = [d for d in mintlang.check(source) if d.code == "E3007"]
    return error


@pytest.mark.parametrize("source", ["DIM arr(5)\narr[2] = 3\n", "DIM arr(5)\nPRINT arr[2]\n"])
def test_the_error_says_where_an_index_goes_and_offers_no_keyword_that_takes_no_axes(source: str) -> None:
    """ARR is most like ERR, which is read alone (``v = ERR``): respelling ``arr[2] = 3`` as ``ERR[2] = 3``
    would be no fix, so neither the message nor a fix offers it."""
    error = _error_3007(source)
    assert "round brackets" in error.message and "ERR" not in error.message
    assert error.fixes == ()


def test_a_misspelt_keyword_with_axes_is_still_offered_the_keyword() -> None:
    error = _error_3007("SPEEED[0] = 1\n")
    assert error.message.endswith("'SPEEED' is not a keyword (did you mean 'SPEED'?)")
    assert [fix.title for fix in error.fixes] == ["Replace with SPEED"]
