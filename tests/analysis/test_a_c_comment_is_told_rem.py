"""A comment begun with C's ``//`` is a syntax error (2003) told that Mint's comments begin with REM.

A remark is REM and the rest of its line, after a statement with or without a colon (000:15506-15515);
``//`` is two divisions with nothing to divide. Writing REM in its place keeps the line's meaning, so the
fix is safe.
"""

from __future__ import annotations

import mintlang
from tests.analysis.checking import apply, covered

DECLARED = "DIM a\n"


def _only(line: str) -> tuple[str, mintlang.Diagnostic]:
    source = DECLARED + line + "\nPRINT a\n"
    (diagnostic,) = mintlang.check(source)
    return source, diagnostic


def test_a_comment_after_a_statement() -> None:
    source, diagnostic = _only("a = 1 // the first")
    assert (diagnostic.code, covered(source, diagnostic)) == ("E2003", "//")
    assert diagnostic.message == "Syntax error: Mint's comments begin with REM"
    (fix,) = diagnostic.fixes
    assert fix.safe
    assert apply(source, fix.edits) == DECLARED + "a = 1 REM the first\nPRINT a\n"


def test_a_comment_on_a_line_of_its_own() -> None:
    source, diagnostic = _only("// set a\na = 1")
    assert diagnostic.message == "Syntax error: Mint's comments begin with REM"
    assert apply(source, diagnostic.fixes[0].edits) == DECLARED + "REM set a\na = 1\nPRINT a\n"
