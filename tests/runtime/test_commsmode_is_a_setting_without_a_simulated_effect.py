"""mint-run accepts COMMSMODE, remembers it and reads it back; the run goes on as before.

COMMSMODE chooses the network a remote comms access, COMMS(node, element), goes over: 0 CANopen, 1 RS485
(000:2376-2379, 000:8338-8368); 0 at power-up, 0 or 1 (000:8360). It has nothing to do with the controller's
own comms array, which COMMS(element) reads and writes whatever the mode. A remote access is not simulated,
and stops the run where it is made; setting the mode is not one. A value outside 0 or 1 is #3 (000:18518-18521);
a terminal after a dot that names none is #35, one that is not a serial port #36 (000:18637-18646), as in
mint check.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from tests.analysis.checking import found
from tests.runtime.running import simulate


def test_commsmode_reads_0_at_power_up_and_what_was_written_after() -> None:
    result = simulate("PRINT COMMSMODE\nCOMMSMODE = 1\nPRINT COMMSMODE\nCOMMSMODE = 0\nPRINT COMMSMODE\n")
    assert result.stop.reason is not StopReason.ERROR
    assert result.terminal == "0\n1\n0\n"


def test_the_comms_array_of_the_controller_is_the_same_in_either_mode() -> None:
    result = simulate("COMMS(1) = 5\nCOMMSMODE = 1\nPRINT COMMS(1)\nCOMMS(2) = 7\nCOMMSMODE = 0\nPRINT COMMS(2)\n")
    assert result.terminal == "5\n7\n"


@pytest.mark.parametrize(
    ("line", "error"), [("COMMSMODE = 2", 3), ("COMMSMODE.5 = 1", 35), ("COMMSMODE._tmLCD1 = 1", 36)]
)
def test_what_mint_check_refuses_stops_the_run_with_the_same_error(line: str, error: int) -> None:
    assert [code for code, _, _ in found(f"{line}\n", controller="nextmove-bx")] == [f"E{error:04d}"]
    result = simulate(f'PRINT "before"\n{line}\n')
    assert result.stop.reason is StopReason.ERROR
    assert (result.err, result.erl) == (error, 2)
    assert result.terminal.startswith("before\n")
