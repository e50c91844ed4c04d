"""An expression as an axis number in square brackets is a syntax error (2003) told what to write instead.

``MOVER[a+1] = 100`` is invalid: the expression is given to a variable first (000:584-589), or, for one axis,
written after the dot, ``POS.(a + 1)`` (000:694-700). The message names the keyword and the expression as
written, so the author reads their own line in it.
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.checking import covered

DECLARED = "DIM a\nDIM b\n"


@pytest.mark.parametrize(
    ("line", "expression", "advice"),
    [
        ("MOVER[a+1] = 100", "a+1", "write MOVER.(a+1), or give a+1 to a variable first"),
        ("b = POS[a + 1]", "a + 1", "write POS.(a + 1), or give a + 1 to a variable first"),
        ("MOVER[0, a*2] = 10, 20", "a*2", "give a*2 to a variable first"),
        ("AXES[0, a+1]", "a+1", "give a+1 to a variable first"),
    ],
)
def test_the_message_names_the_keyword_and_the_expression(line: str, expression: str, advice: str) -> None:
    source = DECLARED + line + "\n"
    (diagnostic,) = [d for d in mintlang.check(source) if d.code == "E2003"]
    assert covered(source, diagnostic) == expression
    assert diagnostic.message == (
        f"Syntax error: an axis number in brackets must be a number or a simple variable: {advice}"
    )
