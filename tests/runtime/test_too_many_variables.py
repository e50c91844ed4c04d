"""mint-run refuses a Mint v4 program with more variables than the variable stack leaves it.

The stack holds 255 variables, 100 on NextMove PC (000:866-868, 000:1907-1913). COMMS and GROUPCOMMS are
always on it (000:18465-18466), an array taking one place (000:1058-1059): 253 are left for the configuration
file and the program together, 98 on NextMove PC. One more is error 3002, "Too many variables" (000:19085-19087),
a compiler error (000:4611-4613): the program does not start, and its message is a compile-time one, ``C``
(000:4584-4588). The configuration file is compiled and run first (000:269-271).
"""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate


def declarations(count: int, first: int = 0) -> str:
    return "".join(f"DIM v{i}\n" for i in range(first, first + count))


@pytest.mark.parametrize(("controller", "room"), [("nextmove-bx", 253), ("nextmove-pc", 98)])
def test_the_last_place_runs_and_one_more_stops_the_program_before_it_starts(controller: str, room: int) -> None:
    fits = simulate(declarations(room) + 'PRINT "ran"\n', controller=controller)
    assert fits.stop.reason is not StopReason.ERROR
    assert "ran" in fits.terminal
    over = simulate('PRINT "before"\n' + declarations(room + 1), controller=controller)
    assert over.stop.reason is StopReason.ERROR
    assert over.err == 3002
    assert "before" not in over.terminal
    assert over.terminal.startswith("C3002: PROGRAM Too many variables")
    assert over.terminal.endswith(f"[line {room + 2}]\n")


def test_the_configuration_files_variables_count_and_it_runs_before_the_program_is_refused() -> None:
    config = "RESETALL\n" + declarations(200) + 'PRINT "configured"\n'
    over = simulate(declarations(54, first=200) + 'PRINT "ran"\n', config=config)
    assert over.err == 3002
    assert "configured" in over.terminal
    assert "ran" not in over.terminal
