"""Giving a value to a command the guide prints no attributes table for is error 2000 in mint-run, as in mint check.

VER's only format is the bare word (000:17166-17167) and LINE's writes a line number and an expression
after the word (000:13638-13639): neither is ever given a value with ``=``, so each is a command, and
writing a value to a command is error 2000 "Read only or Command" (000:18905-18908), an interpreter
error raised by the line when it runs, which #ONERROR sees (000:4614-4619). The run must not stop on it
as a keyword it does not simulate.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate

HANDLER = 'END\n#ONERROR\nPRINT "ERR ", ERR, " ERL ", ERL\nRETURN\n'


@pytest.mark.parametrize("line", ["VER = 1", "LINE = 1"])
def test_both_tools_give_error_2000_on_its_line(line: str) -> None:
    source = f'PRINT "before"\n{line}\nPRINT "after"\n'
    assert [d.code for d in mintlang.check(source + HANDLER) if d.code.startswith("E")] == ["E2000"]
    # the handler sees 2000 on line 2; when it returns, the interpreter error ends the run with its
    # message (000:4614-4615), "after" never printed
    result = simulate(source + HANDLER)
    assert result.terminal == "before\nERR 2000 ERL 2\nR2000: PROGRAM Read only or Command [line 2]\n"
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 2000, 2)


@pytest.mark.parametrize("line", ["VER = 1", "LINE = 1"])
def test_without_a_handler_the_run_stops_with_the_error_at_its_line(line: str) -> None:
    # the controller prints the error with its line (000:4579-4590), the message of 000:18905
    result = simulate(f'PRINT "before"\n{line}\nPRINT "after"\n')
    assert result.terminal == "before\nR2000: PROGRAM Read only or Command [line 2]\n"
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 2000, 2)
