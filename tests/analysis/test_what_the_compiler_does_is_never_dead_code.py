"""DIM and DEFINE act when the program is compiled, wherever they stand: no "code that can never run".

Mint compiles a program before it runs it, and declares its variables then (000:967-970);
arrays are made and filled at compile time, "regardless of where they reside in the
program" (000:1104-1105); macros are substituted at compile time (000:18494). So an array's
DIM, a DIM that only declares, and a DEFINE after an endless loop or an END still do their
work, and W106's fix must not remove them: removing ``DIM tbl(3) = 10, 20, 30`` would leave
the handler that reads it with an undeclared name (3001, 000:19068-19073). A variable's
``DIM b = 10`` gives its value when it runs (the guide's #default routine, 000:1027-1033),
so after END it is still dead code.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.fixes import fix_text
from tests.analysis.placed import placed

HANDLER = "#TIMER\nPRINT tbl(1), b, m\nRETURN\n"


@pytest.mark.parametrize(
    "compiled",
    [
        pytest.param("DIM tbl(3) = 10, 20, 30\nDIM b\nDEFINE m = 5\n", id="array-declaration-macro"),
        pytest.param("DIM tbl(3)\nDIM b\nDEFINE m = 5\n", id="array-without-values"),
    ],
)
def test_declarations_after_an_endless_loop_are_not_dead_code(compiled: str) -> None:
    source = "TIMEREVENT = 50\nLOOP\nENDL\n" + compiled + HANDLER
    assert placed(source, "code", "text") == []


def test_the_fix_removes_the_dead_code_around_a_declaration_and_keeps_it() -> None:
    source = "TIMEREVENT = 50\nEND\nPRINT 1\nDIM tbl(3) = 10, 20, 30\nPRINT 2\nDIM b\nDEFINE m = 5\n" + HANDLER
    assert placed(source, "code", "text") == [("W106", "PRINT 1"), ("W106", "PRINT 2")]
    fixed = fix_text(source, mintlang.check, unsafe=True)
    assert fixed.text == "TIMEREVENT = 50\nEND\nDIM tbl(3) = 10, 20, 30\nDIM b\nDEFINE m = 5\n" + HANDLER


def test_a_variables_value_after_end_is_dead_code() -> None:
    source = "END\nDIM b = 10\n#TIMER\nPRINT b\nRETURN\n"
    assert placed(source, "code", "text") == [("W106", "DIM b = 10")]
