"""SUSPEND pauses the move buffer, never changes what it does (mintlang/MINTMT.md, MT-16).

Whenever the motion is suspended and for however long, the moves end where
they would have ended, the output move between them acts, and they finish no
sooner than they would have.
"""

from __future__ import annotations

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from mintlang.runtime.run import run_source
from mintlang.runtime.simulation import Limits
from tests.fuzzing import examples

PROGRAM = """SPEED(0) = 5000 : ACCEL(0) = 50000 : DECEL(0) = 50000
MOVEBUFFERSIZE(0) = 4
CONTOURMODE(0) = {contour}
MOVER(0) = 4000
MOVEOUTX(0,1) = 1
MOVER(0) = -1500
GO(0)
Wait = {suspend_at}
SUSPEND(0) = {suspending}
Wait = {paused_for}
SUSPEND(0) = 0
Pause IDLE(0)
Print TIME
"""


def _run(contour: int, suspend_at: int, paused_for: int, *, suspending: bool) -> tuple[float, float, int]:
    source = PROGRAM.format(contour=contour, suspend_at=suspend_at, paused_for=paused_for, suspending=int(suspending))
    result = run_source(source, dialect="mintmt", config="RESETALL\n", limits=Limits(until_ms=20_000))
    return result.axes[0].pos, float(result.terminal), result.outputs


@settings(max_examples=examples(12), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    contour=st.sampled_from([0, 1]),
    suspend_at=st.integers(min_value=2, max_value=1800),  # WAIT takes 2 ms or more
    paused_for=st.integers(min_value=2, max_value=400),
)
def test_a_suspended_buffer_ends_where_it_would_have_and_never_sooner(
    contour: int, suspend_at: int, paused_for: int
) -> None:
    position, finished, outputs = _run(contour, suspend_at, paused_for, suspending=True)
    free_position, free_finished, free_outputs = _run(contour, suspend_at, paused_for, suspending=False)
    assert (position, outputs) == (free_position, free_outputs) == (2500.0, 2)
    assert finished >= free_finished
