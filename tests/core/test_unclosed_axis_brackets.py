"""An axis list whose ``]`` is missing says so, not that a ``)`` is one too many.

The guide gives no message of its own for it; a missing closing bracket is a syntax error (2003),
as a missing ``)`` is (000:18920-18924), and only a ``)`` with nothing open is one too many (000:18925-18928).
"""

from __future__ import annotations

import pytest

import mintlang


def _errors(source: str) -> list[tuple[str, str, int]]:
    found = mintlang.check_application(source).program
    return [(d.code, d.message, d.span.start) for d in found if d.code[0] == "E"]


@pytest.mark.parametrize(
    ("source", "column"),
    [
        ("SPEED[0,1) = 4\n", 9),  # closed with the other bracket: the ')' is where the ']' belongs
        ("SPEED[0,1 = 4\n", 13),  # never closed: the statement ends with it open
        ("a = ABS(SPEED[0)\n", 15),  # the innermost open bracket is the axis list's
    ],
)
def test_a_missing_closing_square_bracket_is_named(source: str, column: int) -> None:
    assert _errors(source) == [("E2003", "Syntax error: a ']' is missing", column)]


def test_a_round_bracket_too_many_is_still_2004() -> None:
    assert _errors("SPEED[0] = (2 + 3))\n") == [("E2004", "Parentheses error: there is a ')' too many", 18)]
