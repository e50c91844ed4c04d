"""A string joined to another with ``&``, as Visual Basic writes it, is told PRINT's comma, as ``+`` is
(test_strings_joined_with_plus_are_told_a_comma).

Mint has no string values: PRINT's items follow one another after a comma (000:15299-15302), and its ``&`` is
the bitwise AND (000:1286-1289), so ``"a" & b`` is no expression: a syntax error (2003), which said only that
'&' was unexpected. Between two strings the comma is plainly meant, a safe fix; after a string the fix is
unsafe, since the next ``&`` of ``"a" & b & c`` would be left as an AND of b and c.
"""

from __future__ import annotations

import mintlang
from mintlang.fixes import fix_text
from tests.analysis.checking import apply, covered

DECLARED = "DIM a = 1\n"
MESSAGE = (
    "Syntax error: Mint does not join strings with '&', its bitwise AND: separate the items with ',', "
    "which prints each directly after the one before"
)


def _only(line: str) -> tuple[str, mintlang.Diagnostic]:
    source = DECLARED + line + "\n"
    (diagnostic,) = mintlang.check(source)
    return source, diagnostic


def test_two_strings_are_told_the_comma_with_a_safe_fix() -> None:
    source, diagnostic = _only('PRINT "a" & "b"')
    assert (diagnostic.code, covered(source, diagnostic), diagnostic.message) == ("E2003", "&", MESSAGE)
    (fix,) = diagnostic.fixes
    assert fix.safe
    assert apply(source, fix.edits) == DECLARED + 'PRINT "a", "b"\n'


def test_a_string_and_a_value_are_told_the_comma_with_an_unsafe_fix() -> None:
    for line, fixed in (('PRINT "a = " & a', 'PRINT "a = ", a'), ('? a & " mm"', '? a, " mm"')):
        source, diagnostic = _only(line)
        assert (covered(source, diagnostic), diagnostic.message) == ("&", MESSAGE)
        (fix,) = diagnostic.fixes
        assert not fix.safe
        assert apply(source, fix.edits) == DECLARED + fixed + "\n"


def test_a_chain_of_strings_is_fixed_at_once_and_an_and_of_two_values_stays() -> None:
    # one '&' at a time, the next was the same finding again, so --fix undid the round and fixed nothing
    chained = DECLARED + 'PRINT "a" & "b" & "c"\n'
    assert fix_text(chained, mintlang.check, unsafe=False).text == DECLARED + 'PRINT "a", "b", "c"\n'
    anded = DECLARED + 'PRINT "bits " & a & 3\n'  # a & 3 is an AND (000:1286-1289)
    assert fix_text(anded, mintlang.check, unsafe=True).text == DECLARED + 'PRINT "bits ", a & 3\n'


def test_and_written_as_a_word_is_not_told_of_joining() -> None:
    (diagnostic,) = mintlang.check(DECLARED + 'PRINT "a" AND a\n')
    assert "join strings" not in diagnostic.message
