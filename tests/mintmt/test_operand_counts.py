"""A function or a command given more or fewer values than its v4 format writes is a syntax error in MintMT too.

The notes show no function or terminal command of their own, so MintMT reads v4's (MT-1): ``POW(x, y)``
takes two values (000:15152), ``SIN(<angle>)`` one (000:15944), ``LOCATE`` a column and a row
(000:13685), ``LINE`` a line number and what to print (000:13640). A statement that does not match its
syntax is 2003 (000:18920-18922), which the compiler reports before the program runs: ``mint-run``
refuses the file as ``mint check`` reports it. A keyword's own round brackets (``POS(0)``) are its axes,
no call, and take no count from a format.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.runtime.run import run_source


@pytest.mark.parametrize(
    "line",
    [
        pytest.param("a = POW(2)", id="000:15152 POW takes two values"),
        pytest.param("a = SIN(30, 2)", id="000:15944 SIN takes one"),
        pytest.param("LOCATE 10", id="000:13685 LOCATE takes a column and a row"),
        pytest.param("LINE", id="000:13640 LINE takes a line number and what to print"),
    ],
)
def test_a_wrong_count_is_a_syntax_error_before_the_run(line: str) -> None:
    source = f"DIM a\n{line}\n"
    assert [d.code for d in mintlang.check(source, dialect="mintmt") if d.code.startswith("E")] == ["E2003"]
    result = run_source(source, dialect="mintmt")
    assert result.refused
    assert result.stop.message.startswith("C2003: PROGRAM Syntax error")


@pytest.mark.parametrize(
    "line", ["a = POW(2, 3)", "a = SIN(30)", "LOCATE 1, 2", 'LINE 1, "x"', "a = POS(0)", "MOVER(0, 1) = 10, 20"]
)
def test_the_counts_the_formats_write_are_no_error(line: str) -> None:
    source = f"DIM a\n{line}\n"
    assert [d.code for d in mintlang.check(source, dialect="mintmt") if d.code.startswith("E")] == []
