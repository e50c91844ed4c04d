"""A run stopped by the wall clock while a PAUSE waits for a homing cycle says what the cycle still looks for.

A cycle ends only on its home switch or its encoder's index pulse (HM-3 to HM-5: modes 0 and 2 seek the
HOMEINPUT switch, modes 4 and 6 search for the index). The simulation gives neither unless a scenario does,
so a program that homes first ran until the wall-clock limit with nothing but the PAUSE to show for it.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import run_source
from mintlang.runtime.simulation import Limits

_HOMING = "HOMEINPUT.0 = 8\nHOMESPEED.0 = 1000\nHOME.0 = {mode}\nPAUSE IDLE.0\nPRINT POS.0\n"


@pytest.mark.parametrize(
    ("mode", "waiting"),
    [
        pytest.param(
            4,
            "axis 0 is still homing: it searches for its encoder's index pulse, which no scenario gives it"
            " (REM @sim index 0 every N)",
            id="index mode without an index pulse",
        ),
        pytest.param(
            0,
            "axis 0 is still homing: it seeks its home switch, input 8, which has not turned active",
            id="switch mode",
        ),
    ],
)
def test_the_wall_limit_names_what_the_cycle_waits_for(mode: int, waiting: str) -> None:
    limits = Limits(max_wall_s=0.2)
    result = run_source(_HOMING.format(mode=mode), config="RESETALL\n", controller="nextmove-bx", limits=limits)
    assert result.stop.reason is StopReason.WALL_LIMIT
    assert result.stop.message.endswith(f"s of wall time; {waiting}")
