"""A command is given as many operands as its format writes, or it is error 2003.

LOCATE takes a column and a row (000:13685; ``LOCATE 10,10`` and ``LOCATE #3 10,10``, 000:13692-13693),
PROTECT a password (000:15385), RUN an optional buffer (000:15723). LINE takes a line number and
what to print there, which may be a whole PRINT list (``LINE #3 2, "A = ", a USING 5,2`` and a
trailing comma, 000:13640-13661), with PRINT's ``;`` between its items (000:15299-15302). Another count,
or a ``;`` between other operands, does not match the statement's syntax (#2003, 000:18920). ``LOCATE 10``
and ``LINE 1`` passed mint check.
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.placed import placed_codes


@pytest.mark.parametrize(
    "source",
    [
        pytest.param('LOCATE 10,10 : PRINT "Column 10, Row 10"\n', id="locate"),
        pytest.param('LOCATE #3 10,10 : PRINT "Column 10, Row 10"\n', id="locate-on-a-terminal"),
        pytest.param('DIM a\nLINE #3 2, "A = ", a USING 5,2\n', id="line-with-a-print-list"),
        pytest.param('LINE 4,"SETUP START MANUAL",\n', id="line-with-a-trailing-comma"),
        pytest.param('DIM a\nLINE 2, "A = "; a;\n', id="line-with-semicolons-as-print"),
        pytest.param("RUN\n", id="run-alone"),
        pytest.param("PROTECT 1234\n", id="protect"),
    ],
)
def test_the_manuals_operands_are_accepted(source: str) -> None:
    assert placed_codes(source) == []


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        pytest.param("LOCATE 10\n", [("E2003", 1, 1)], id="locate-without-a-row"),
        pytest.param("LOCATE 1, 2, 3\n", [("E2003", 1, 1)], id="locate-with-a-third"),
        pytest.param("LOCATE\n", [("E2003", 1, 1)], id="locate-alone"),
        pytest.param("LINE 1\n", [("E2003", 1, 1)], id="line-without-text"),
        pytest.param("PROTECT\n", [("E2003", 1, 1)], id="protect-without-a-password"),
        pytest.param("LOCATE 1; 2\n", [("E2003", 1, 9)], id="locate-with-print-s-separator"),
        pytest.param('LINE 1; "a"\n', [("E2003", 1, 7)], id="semicolon-after-the-row"),
    ],
)
def test_another_count_is_error_2003(source: str, expected: list[tuple[str, int, int]]) -> None:
    assert placed_codes(source) == expected


def test_the_message_gives_the_count_and_the_format() -> None:
    (diagnostic,) = mintlang.check("LOCATE 10\n")
    assert "LOCATE takes 2 operands (LOCATE {#<terminal>} <column>,<row>), not 1" in diagnostic.message
