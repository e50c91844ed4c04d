"""Going back is re-running: every earlier point, reached again, holds the state the first run had there.

In-process, on generated programs that wait, move axes, read keys and inputs
changing on a schedule and take timer events (``tests/runtime/programs.py``):
the state at each stop of a forward walk equals the state at the same point
reached again by a re-run, whether the point is found among the run's recent
points or by a scan from the start.
"""

from __future__ import annotations

import queue
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, note, settings
from hypothesis import strategies as st

from mintlang.runtime.debugger import execution as execution_module
from mintlang.runtime.debugger import stepping
from mintlang.runtime.debugger.breakpoints import Breakpoints
from mintlang.runtime.debugger.execution import Execution
from mintlang.runtime.debugger.launch import layout, prepare
from mintlang.runtime.observation import axis_state
from mintlang.runtime.run import RunResult, run_source
from mintlang.runtime.simulation import Limits
from tests.runtime.programs import UNTIL_MS, Program, timed_programs

STOPS = 12  # forward stops recorded per program: each step back is a re-run, so the walk stays short
TIMEOUT_S = 60


class Harness:
    """A debugger without an editor: the test waits for each stop itself."""

    def __init__(self, source: str, folder: Path) -> None:
        path = folder / "generated.mnt"
        path.write_text(source, encoding="utf-8")
        application = prepare({"program": str(path), "untilMs": UNTIL_MS, "dialect": "v4", "noConfig": True})
        self.execution = Execution(application, Breakpoints(layout(application)), self)
        self.reports: queue.Queue[str] = queue.Queue()
        self.printed = ""  # what the console was sent of the program's output
        self.result: RunResult | None = None

    def stopped(self, reason: str, description: str | None) -> None:
        self.reports.put(reason)

    def output(self, text: str, category: str) -> None:
        if category == "stdout":
            self.printed += text

    def finished(self, result: RunResult | None, problem: str | None) -> None:
        self.result = result
        self.reports.put("finished")

    def wait(self) -> str:
        return self.reports.get(timeout=TIMEOUT_S)

    def state(self) -> tuple[object, ...]:
        """Everything a stop shows: the point, the variables and arrays, the time, each axis and the I/O."""
        execution = self.execution
        controller = execution.controller
        assert controller is not None and execution.point is not None
        vm = controller.vm
        axes = tuple(axis_state(axis) for axis in controller.axes[:2])
        io = (controller.io.active, controller.io.out)
        return execution.point, tuple(vm.scalars), tuple(map(tuple, vm.arrays)), controller.clock.now, axes, io


def _forward(harness: Harness, stops: int) -> list[tuple[object, ...]]:
    """The state at each of the first ``stops`` stops of a walk by ``stepIn`` from the entry (fewer if it ends)."""
    execution = harness.execution
    execution.start(stepping.entry())
    seen = []
    while harness.wait() != "finished":
        seen.append(harness.state())
        if len(seen) == stops:
            break
        assert execution.point is not None
        execution.resume(stepping.step_in(execution.point))
    return seen


def _walk_and_return(program: Program) -> None:
    note(program.source)
    with tempfile.TemporaryDirectory() as folder:
        forward = _forward(Harness(program.source, Path(folder)), STOPS)
        harness = Harness(program.source, Path(folder))  # paused at the last stop, however the first walk ended
        assert _forward(harness, len(forward)) == forward
        execution = harness.execution
        while execution.point is not None:
            at = execution.point  # stepping back is the reverse of next: to this frame's or a caller's statement
            earlier = [state for state in forward if state[0].count < at.count and state[0].depth <= at.depth]
            if not earlier:
                break
            execution.step_back(at)
            assert harness.wait() == "step"
            assert harness.state() == earlier[-1]
        execution.terminate()


property_test = settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@property_test
@given(program=timed_programs())
def test_each_step_back_reaches_the_state_the_forward_walk_had_there(program: Program) -> None:
    _walk_and_return(program)


@property_test
@given(program=timed_programs())
def test_stepping_back_by_a_scan_from_the_start_reaches_the_same_states(program: Program) -> None:
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(execution_module, "RECENT", 1)  # nothing recent to go back to: every step back scans
        _walk_and_return(program)


@property_test
@given(program=timed_programs(), forward=st.integers(min_value=0, max_value=10), back=st.integers(0, 5))
def test_a_session_that_steps_and_steps_back_ends_as_the_run_without_the_debugger(
    program: Program, forward: int, back: int
) -> None:
    """However the session went back and forth, the run ends where, when and as an uninterrupted run does,
    and the console shows what that run printed, once."""
    note(program.source)
    expected = run_source(program.source, limits=Limits(until_ms=UNTIL_MS, max_wall_s=None))
    with tempfile.TemporaryDirectory() as folder:
        harness = Harness(program.source, Path(folder))
        execution = harness.execution
        reported = bool(_forward(harness, forward + 1))  # paused at the last stop walked to, unless it ended
        for _ in range(back if reported and execution.point is not None else 0):
            execution.step_back(execution.point)
            harness.wait()
        while execution.point is not None:  # on to the end, through any stop (an error ending the run)
            execution.resume(stepping.cont(execution.point.count))
            harness.wait()
        execution.terminate()
    result = harness.result
    assert result is not None
    assert (result.stop, result.err, result.axes, result.outputs) == (
        expected.stop,
        expected.err,
        expected.axes,
        expected.outputs,
    )
    if not expected.terminal_dropped:
        assert harness.printed == expected.terminal
