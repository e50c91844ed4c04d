"""``a ^ 2``, other BASICs' power operator, is a syntax error (2003) told Mint's POW.

Mint's operators are ``+ - * /`` and MOD (000:1274-1282); the power x to the y is the function POW(x, y)
(000:1410, 15151-15158). The message pointed at the ``2`` as unexpected. With one token on each side the
rewrite is plainly meant and keeps the order of evaluation (a function binds before any operator,
000:1418-1420), so its fix is safe; with more, the message alone says how.
"""

from __future__ import annotations

import mintlang
from tests.analysis.checking import apply, covered

DECLARED = "DIM a = 2\nDIM b = 0\n"


def _only(line: str) -> tuple[str, mintlang.Diagnostic]:
    source = DECLARED + line + "\nPRINT b\n"
    (diagnostic,) = mintlang.check(source)
    return source, diagnostic


def test_a_caret_is_told_pow_with_a_safe_fix() -> None:
    source, diagnostic = _only("b = 3 * a ^ 2")
    assert (diagnostic.code, covered(source, diagnostic)) == ("E2003", "^")
    assert diagnostic.message == "Syntax error: Mint has no '^': write POW(a, 2)"
    (fix,) = diagnostic.fixes
    assert fix.safe
    assert apply(source, fix.edits) == DECLARED + "b = 3 * POW(a, 2)\nPRINT b\n"


def test_an_expression_beside_the_caret_is_told_how_without_a_fix() -> None:
    _, diagnostic = _only("b = (a + 1) ^ 2")
    assert diagnostic.message == "Syntax error: Mint has no '^': write POW(x, y) for x to the power y"
    assert diagnostic.fixes == ()
