"""A string where a value is due is a syntax error (2003) told that Mint's values are numbers.

Mint supports numeric variables only, not string ones (000:929); a string is printed (PRINT, 000:15299) or is
INPUT's prompt. A character in single quotes is a number, its ASCII code, as INKEY returns one (000:801-806):
a string of one character compared or assigned is told that constant, with a fix that writes it, unsafe
because the quotes say the author thought of text.
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.checking import apply, covered

DECLARED = "DIM a\n"
NUMBERS = "Mint's values are numbers: a string can only be printed, or be INPUT's prompt"


@pytest.mark.parametrize(
    ("line", "fixed"),
    [
        ('IF a = "y" THEN PRINT 1', "IF a = 'y' THEN PRINT 1"),
        ('a = "A"', "a = 'A'"),
        ('PAUSE a <> "q"', "PAUSE a <> 'q'"),
    ],
)
def test_one_character_is_told_the_character_constant(line: str, fixed: str) -> None:
    source = DECLARED + line + "\n"
    (diagnostic,) = mintlang.check(source)
    assert diagnostic.code == "E2003"
    assert covered(source, diagnostic) == line[line.index('"') : line.rindex('"') + 1]
    character = fixed[fixed.index("'") : fixed.rindex("'") + 1]
    assert diagnostic.message == (
        f"Syntax error: {NUMBERS}; a character in single quotes, {character}, is its ASCII code"
    )
    (fix,) = diagnostic.fixes
    assert not fix.safe
    assert apply(source, fix.edits) == DECLARED + fixed + "\n"


@pytest.mark.parametrize("line", ['a = "abc"', 'DIM s = "hello"', 'IF a = "yes" THEN PRINT 1'])
def test_a_longer_string_is_told_that_values_are_numbers(line: str) -> None:
    source = DECLARED + line + "\n"
    (diagnostic,) = [d for d in mintlang.check(source) if d.code == "E2003"]
    assert diagnostic.message == f"Syntax error: {NUMBERS}"
    assert diagnostic.fixes == ()


def test_strings_printed_and_prompts_are_read() -> None:
    assert mintlang.check(DECLARED + 'PRINT "a = ", a\nINPUT "A = ", a\n') == []
