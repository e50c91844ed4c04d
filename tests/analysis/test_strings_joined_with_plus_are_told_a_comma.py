"""A string joined to another with ``+``, as other BASICs and C++ write it, is told PRINT's comma.

Mint has no string values: PRINT takes strings and expressions as items separated by commas or semicolons,
and a comma prints the next item directly after the one before (000:15299-15302); LINE takes what PRINT
takes (000:15353). ``"a" + "b"`` is no expression, so the statement is a syntax error (000:18920-18924).
Between two strings the comma is plainly what was meant, a safe fix; after a string, ``+`` may have been
meant as the sum of what follows (``"Total " + a + b``), so the fix is offered as unsafe there.
"""

from __future__ import annotations

import mintlang
from mintlang.fixes import fix_text
from tests.analysis.checking import apply, covered

DECLARED = "DIM a = 1\n"
MESSAGE = (
    "Syntax error: Mint does not join strings with '+': separate the items with ',', which prints each "
    "directly after the one before"
)


def _only(line: str) -> tuple[str, mintlang.Diagnostic]:
    source = DECLARED + line + "\n"
    (diagnostic,) = mintlang.check(source)
    return source, diagnostic


def test_two_strings_are_told_the_comma_with_a_safe_fix() -> None:
    source, diagnostic = _only('PRINT "a" + "b"')
    assert (diagnostic.code, covered(source, diagnostic), diagnostic.message) == ("E2003", "+", MESSAGE)
    (fix,) = diagnostic.fixes
    assert fix.safe
    assert apply(source, fix.edits) == DECLARED + 'PRINT "a", "b"\n'


def test_a_string_and_a_value_are_told_the_comma_with_an_unsafe_fix() -> None:
    for line, fixed in (('PRINT "a = " + a', 'PRINT "a = ", a'), ('? a + " mm"', '? a, " mm"')):
        source, diagnostic = _only(line)
        assert (covered(source, diagnostic), diagnostic.message) == ("+", MESSAGE)
        (fix,) = diagnostic.fixes
        assert not fix.safe
        assert apply(source, fix.edits) == DECLARED + fixed + "\n"


def test_every_join_beside_a_string_is_a_comma_in_one_fix() -> None:
    # fixed one '+' at a time, the next one was the same finding again, so --fix undid the round and fixed nothing;
    # a '+' between two values may be a sum (000:15299-15302 joins items, not values) and stays
    for line, fixed, safe in (
        ('PRINT "a" + "b" + "c"', 'PRINT "a", "b", "c"', True),
        ('PRINT "Speed " + a + " mm/s"', 'PRINT "Speed ", a, " mm/s"', False),
        ('PRINT "Total " + a + a', 'PRINT "Total ", a + a', False),
    ):
        source = DECLARED + line + "\n"
        assert fix_text(source, mintlang.check, unsafe=not safe).text == DECLARED + fixed + "\n"
        assert fix_text(source, mintlang.check, unsafe=False).text == (DECLARED + fixed + "\n" if safe else source)


def test_line_is_told_it_too() -> None:
    _, diagnostic = _only('LINE 2, "a = " + a')
    assert diagnostic.message == MESSAGE


def test_a_string_in_another_statement_is_not_told_of_print() -> None:
    source = 'DIM x\nINPUT "a" + "b", x\nPRINT x\n'
    (diagnostic,) = mintlang.check(source)
    assert "join strings" not in diagnostic.message
