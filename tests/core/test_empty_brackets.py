"""Empty brackets are a syntax error, not a bracket too many.

Error 2004 is an incorrect number of brackets within an expression (000:18925-18928,
``a = (b + 2) *3)``); ``ABS()`` has as many ``)`` as ``(``, and what is wrong is the value
missing between them, a statement syntactically incorrect: 2003 (000:18920-18922).
"""

from __future__ import annotations

import pytest

import mintlang


@pytest.mark.parametrize(
    ("statement", "named"),
    [
        pytest.param("a = ABS()", "ABS", id="function"),
        pytest.param("a = POW( )", "POW", id="two-argument-function"),
        pytest.param("PRINT SQRT()", "SQRT", id="in-print"),
        pytest.param("a = COMMS()", "COMMS", id="comms"),
        pytest.param("a = 1 + ()", "", id="bare-brackets"),
    ],
)
def test_empty_brackets_are_a_syntax_error_at_the_brackets(statement: str, named: str) -> None:
    source = f"DIM a\n{statement}\n"
    (diagnostic,) = mintlang.parse(source).diagnostics
    written = source[diagnostic.span.start : diagnostic.span.end]
    assert (diagnostic.code, written.replace(" ", "")) == ("E2003", "()")
    assert diagnostic.message == f"Syntax error: nothing between the brackets{f' of {named}' if named else ''}"


def test_a_bracket_too_many_is_still_2004() -> None:
    # 000:18927-18928
    (diagnostic,) = mintlang.parse("DIM a\nDIM b\na = (b + 2) *3)\n").diagnostics
    assert diagnostic.code == "E2004"
