"""A program waiting for a jogging axis to stop, with nothing to stop it, is told the jog is why.

A jog runs until it is told to stop or an error ends it; JOG = 0 or STOP stop it (000:12671-12673). A
PAUSE IDLE on such an axis, with no event, input or timer left that could run a STOP, waits for good:
a deadlock (W-4), and the message names the axis that jogs rather than saying nothing moves.
"""

from __future__ import annotations

from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate


def test_a_pause_on_a_jog_nothing_stops_names_the_jog() -> None:
    result = simulate("DRIVEENABLE.0 = 1\nJOG.0 = 10\nPAUSE IDLE.0\nPRINT 1\n")
    assert result.stop.reason is StopReason.DEADLOCK
    assert result.stop.message.endswith(
        ": axis 0 jogs until JOG = 0, STOP or an error stops it, and nothing left to run can give one"
    )
