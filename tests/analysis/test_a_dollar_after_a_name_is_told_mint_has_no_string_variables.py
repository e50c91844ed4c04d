"""A ``$`` written after a name, as other BASICs name a string variable (``DIM a$``), is a syntax error (2003)
told that Mint has none: its variables hold numbers only (000:929)."""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.checking import covered

TOLD = "Syntax error: '$' after a name: Mint has no string variables, a variable holds a number"


@pytest.mark.parametrize("source", ["DIM a$\n", "DIM name$\nname$ = 1\n"])
def test_the_dollar_is_told(source: str) -> None:
    diagnostics = [d for d in mintlang.check(source) if d.code == "E2003"]
    assert diagnostics
    assert all(covered(source, d) == "$" and d.message == TOLD for d in diagnostics)


@pytest.mark.parametrize("source", ["PRINT $3\n", "$3 PRINT 1\n", "DIM a $\n"])
def test_a_dollar_elsewhere_keeps_its_message(source: str) -> None:
    (diagnostic,) = [d for d in mintlang.check(source) if d.code == "E2003"]
    assert diagnostic.message == "Syntax error: unexpected character '$'"
