"""A run stopped by the wall clock while a PAUSE waits for a homing cycle says what the cycle still looks for.

A cycle ends only on its home switch or its encoder's index pulse (HM-3 to HM-5: modes 0 and 2 seek the
HOMEINPUT switch, modes 4 and 6 search for the index). The simulation gives neither unless a scenario does,
so a program that homes first ran until the wall-clock limit with nothing but the PAUSE to show for it.

The index is polled every 2 ms, as the profiler polls it (runtime/BEHAVIOUR.md, homing): searched for at
HOMESPEED / HOMEBACKOFF (000:11437-11443), 40000 / 10 = 4000 counts/s by default (000:9033-9035), the axis covers
8 counts a poll, so a pulse 1 count wide, the scenario's default, falls between two polls and is never seen.
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


_OFF_THE_PULSE = "MOVEA.0 = 10 : GO.0\nPAUSE IDLE.0\nHOME.0 = 4\nPAUSE IDLE.0\n"  # seeks the pulse at 0 from 10


def test_an_index_pulse_narrower_than_a_polls_travel_is_named_with_the_width_it_needs() -> None:
    source = "REM @sim index 0 every 4000\n" + _OFF_THE_PULSE
    result = run_source(source, config="RESETALL\n", controller="nextmove-bx", limits=Limits(max_wall_s=0.2))
    assert result.stop.reason is StopReason.WALL_LIMIT
    assert result.stop.message.endswith(
        "s of wall time; axis 0 is still homing: it searches for its encoder's index pulse, 1 count wide, which"
        " it passes between two polls at 4000 counts/s (8 counts every 2 ms): make it at least 8 counts wide"
        " (REM @sim index 0 every 4000 width 8)"
    )


def test_the_width_the_message_names_is_enough_for_the_cycle_to_find_the_pulse() -> None:
    source = "REM @sim index 0 every 4000 width 8\n" + _OFF_THE_PULSE
    result = run_source(source, config="RESETALL\n", controller="nextmove-bx", limits=Limits(max_wall_s=5.0))
    assert result.stop.reason is StopReason.END
