"""A long expression within the line limit runs: a v4 line takes 255 characters (000:255, 000:18455),
and ``a = 1+1+...+1`` with 111 ones is 225 of them. Each expression was generated as one Python
function whose text nested two brackets an addition or multiplication, and Python compiles no more
than 200: mint-run stopped with a SyntaxError traceback ("too many nested parentheses"), whatever
statement held the expression. The values are worked out by hand: 111 ones make 111, and 1 times
itself any number of times is 1."""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import run_source

ONES = "+".join(["1"] * 111)


@pytest.mark.parametrize(
    ("program", "printed"),
    [
        pytest.param(f"DIM a\na = {ONES}\nPRINT a\n", "111", id="assignment"),
        pytest.param(f"PRINT {ONES}\n", "111", id="print"),
        pytest.param(f"DIM a\nIF {ONES} = 111 THEN a = 7\nPRINT a\n", "7", id="if-then"),
        pytest.param("DIM a = 1\nWHILE " + "*".join(["a"] * 110) + " > 5\nENDW\nPRINT a\n", "1", id="while"),
    ],
)
def test_a_long_expression_gives_its_value(program: str, printed: str) -> None:
    result = run_source(program)
    assert result.stop.reason is StopReason.END
    assert result.terminal.strip() == printed
