"""FEEDRATE, FEEDRATEMODE and FEEDRATEOVERRIDE run in Mint v4 on the NextMoves, as the v4 guide describes them.

The keyword table gives the three to NextMove PCI, PC and BX (000:17611-17613). SPEED and FEEDRATE set
one slew speed (000:16188-16190); in speed mode, FEEDRATEMODE 0 (000:16220), a SPEED written later
reaches the moves already loaded (000:16192-16193, 16221-16229: both moves of the guide's example run at
30), and in feedrate mode each move keeps the speed it was loaded with (000:16193-16195, 3302-3304).
They stopped a v4 run as not simulated, though MintMT's runs, which follow the same model, had them.

Worked by hand: ACCEL = DECEL = 50000 units/s², SCALE 1. A move of 20 at speed v takes 20 / v + v / 50000 s
(ramps of v / 50000 s each, covering v² / 100000 between them); each move is a whole trapezoid, the
second starting when the first ends, and GO's moves start on the tick after it (2 ms, T-6).
At 30 then 30: 2 x (666.67 + 0.6) = 1334.5 ms, so the axis is idle at 1336.5 ms; at 50 then 30:
(400 + 1) + (666.67 + 0.6) = 1068.3 ms, idle at 1070.3 ms.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate

_PROGRAM = """ACCEL.0 = 50000 : DECEL.0 = 50000
MOVEBUFFERSIZE.0 = 4
FEEDRATEMODE.0 = {mode}
SPEED.0 = 50
MOVER.0 = 20
SPEED.0 = 30
MOVER.0 = 20
GO.0
PAUSE IDLE.0
PRINT "idle at ", TIME, " at ", POS.0
"""


@pytest.mark.parametrize(("mode", "idle_ms"), [(0, 1336.5), (1, 1070.3)], ids=["speed mode", "feedrate mode"])
def test_the_guides_two_moves_run_at_the_speed_the_mode_gives_them(mode: int, idle_ms: float) -> None:
    result = simulate(_PROGRAM.format(mode=mode))
    assert result.stop.reason is StopReason.END, result.stop
    time, position = result.terminal.split("idle at ")[1].split(" at ")
    assert float(position) == 40
    assert abs(float(time) - idle_ms) <= 2  # the 2 ms tick on which the axis is seen idle


def test_feedrate_writes_the_slew_speed_speed_reads() -> None:
    # 000:16188-16190, 16218-16219: SPEED = 20 and FEEDRATE = 20 are equivalent
    result = simulate('FEEDRATE.0 = 20\nPRINT SPEED.0, " ", FEEDRATE.0\n')
    assert result.terminal == "20 20\n"


def test_feedrateoverride_scales_the_speed_of_a_move() -> None:
    # a percentage multiplier of SPEED (000:16212-16213, 3305): 50 % of 40 is 20, so 20 units take 1 s
    source = (
        "ACCEL.0 = 50000 : DECEL.0 = 50000\nFEEDRATEOVERRIDE.0 = 50\nSPEED.0 = 40\nMOVER.0 = 20\nGO.0\n"
        "PAUSE IDLE.0\nPRINT TIME\n"
    )
    result = simulate(source)
    assert abs(float(result.terminal) - (2 + 1000 + 0.4)) <= 2


def test_they_are_not_the_mintdrives() -> None:
    # NextMove only (000:17611-17613): error 17 on MintDrive, as for any keyword a controller lacks
    result = simulate("FEEDRATE.0 = 20\n", controller="mintdrive")
    assert result.err == 17
