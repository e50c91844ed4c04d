"""Which digital inputs fire the fast position latch, controller by controller.

The guide's table (000:5868-5888) calls #FASTIN0..3 "in response to the corresponding digital
inputs": on the NextMove PCI, digital inputs 0, 1, 2 and 3; on the MintDrive and the ServoNode 51,
inputs 0 and 2; the NextMove PC and BX have dedicated fast inputs of their own, which a digital
input does not fire (a scenario's fast input does). The latch takes the position of every axis
(000:4956-4957) and the handler is called within the next servo tick (000:4959).
"""

from __future__ import annotations

import pytest

from tests.runtime.running import simulate

PROGRAM = (
    "REM @sim input {channel} 1 at 100\nREM @sim input {channel} 1 at 200\n"
    'DIM calls\nDIM latched = -1\nMOVEA.0 = 1000 : GO.0\nWAIT = 400\nPRINT calls, " ", latched\nEND\n'
    "#FASTIN{channel}\ncalls = calls + 1\nlatched = FASTPOS.0\nRETURN\n"
)


@pytest.mark.parametrize(
    ("controller", "channel"),
    [("nextmove-pci", 0), ("nextmove-pci", 3), ("mintdrive", 2), ("servonode51", 0)],
)
def test_a_digital_input_wired_to_a_fast_input_latches_once_on_its_rising_edge(controller: str, channel: int) -> None:
    result = simulate(PROGRAM.format(channel=channel), controller=controller)
    calls, latched = result.terminal.split()
    assert calls == "1"  # the second record leaves the input high: no second edge
    assert float(latched) > 0  # the axis had moved by the time the input rose at 100 ms


@pytest.mark.parametrize("controller", ["nextmove-pc", "nextmove-bx"])
def test_a_digital_input_does_not_fire_a_dedicated_fast_input(controller: str) -> None:
    result = simulate(PROGRAM.format(channel=0), controller=controller)
    assert result.terminal == "0 -1\n"
