"""Two values PRINT is given with nothing between them are a syntax error (2003) told PRINT's separators.

PRINT's values are separated by semicolons or commas: a comma prints the next one directly after, a
semicolon at the next tab stop (000:15299-15302). A statement the controller cannot read is a syntax error
(000:18920-18924). Which of the two the author meant is theirs to say, so no fix is offered.
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.checking import covered

DECLARED = "DIM a\nDIM b\n"
TOLD = (
    "Syntax error: PRINT's values are separated by ',' (the next printed directly after) or ';' (at the next tab stop)"
)


@pytest.mark.parametrize(
    ("line", "second"),
    [
        ("PRINT a b", "b"),
        ('PRINT "Position is: " POS.0', "POS"),
        ("? POS.0 POS.1", "POS"),
        ('PRINT a "mm"', '"mm"'),
        ("PRINT a HEX b", "HEX"),
    ],
)
def test_the_second_value_is_told_the_separators(line: str, second: str) -> None:
    source = DECLARED + line + "\n"
    (diagnostic,) = [d for d in mintlang.check(source) if d.severity is mintlang.Severity.ERROR]
    assert diagnostic.code == "E2003"
    assert covered(source, diagnostic) == second
    assert diagnostic.message == TOLD
    assert diagnostic.fixes == ()


def test_a_command_after_a_value_is_not_taken_for_a_value() -> None:
    (diagnostic,) = mintlang.check('PRINT "Teach mode" BEEP\n')
    assert diagnostic.code == "E2003"
    assert diagnostic.message != TOLD


@pytest.mark.parametrize("line", ["PRINT 2.5e2", "PRINT 2.5mm"])
def test_a_word_joined_to_a_number_is_not_taken_for_a_second_value(line: str) -> None:
    (diagnostic,) = mintlang.check(line + "\n")
    assert diagnostic.code == "E2003"
    assert diagnostic.message != TOLD


def test_values_with_their_separators_are_read() -> None:
    assert mintlang.check(DECLARED + 'PRINT a, b; "mm"; HEX b\n') == []
