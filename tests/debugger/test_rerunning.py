"""Going back is re-running: every earlier point, reached again, holds the state the first run had there.

In-process, on generated programs that wait, move axes, read keys and inputs
changing on a schedule and take timer events (``tests/runtime/programs.py``):
the state at each stop of a forward walk equals the state at the same point
reached again by a re-run from a checkpoint, whether the point is found among
the run's recent points or by a scan, and the stops of a walk forward again
from there equal the first walk's. Checkpoints are taken as shipped, or as
often as every tick and thinned hard (so that re-runs start from checkpoints
taken by earlier re-runs, and some from the start), or not at all.
"""

from __future__ import annotations

import queue
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, note, settings
from hypothesis import strategies as st

from mintlang.runtime import snapshot
from mintlang.runtime.debugger import checkpoints, stepping
from mintlang.runtime.debugger import execution as execution_module
from mintlang.runtime.debugger.breakpoints import Breakpoints
from mintlang.runtime.debugger.execution import Execution
from mintlang.runtime.debugger.launch import layout, prepare
from mintlang.runtime.observation import axis_state
from mintlang.runtime.run import RunResult, run_source
from mintlang.runtime.simulation import Limits
from tests.runtime.programs import UNTIL_MS, Program, timed_programs

STOPS = 12  # forward stops recorded per program: each step back is a re-run, so the walk stays short
TIMEOUT_S = 60
SHIPPED = (checkpoints.INTERVAL, checkpoints.DENSE, checkpoints.LIMIT)
CHECKPOINTING = st.sampled_from([SHIPPED, (1, 1, 3), (3, 2, 6)])  # (interval of work, kept per spacing, limit)


def _checkpointing(patch: pytest.MonkeyPatch, interval: int, dense: int, limit: int) -> None:
    patch.setattr(execution_module, "INTERVAL", interval)
    patch.setattr(checkpoints, "DENSE", dense)
    patch.setattr(checkpoints, "LIMIT", limit)


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
    """Walk forward, back by ``stepBack`` as far as it goes, then forward again: each stop as the first walk's."""
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
        for state in [state for state in forward if execution.point and state[0].count > execution.point.count]:
            assert execution.point is not None
            execution.resume(stepping.step_in(execution.point))
            assert harness.wait() == "step"
            assert harness.state() == state
        execution.terminate()


property_test = settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@property_test
@given(program=timed_programs(), spacing=CHECKPOINTING)
def test_each_step_back_reaches_the_state_the_forward_walk_had_there(
    program: Program, spacing: tuple[int, int, int]
) -> None:
    with pytest.MonkeyPatch.context() as patch:
        _checkpointing(patch, *spacing)
        _walk_and_return(program)


@property_test
@given(program=timed_programs(), spacing=CHECKPOINTING)
def test_stepping_back_by_a_scan_reaches_the_same_states(program: Program, spacing: tuple[int, int, int]) -> None:
    with pytest.MonkeyPatch.context() as patch:
        _checkpointing(patch, *spacing)
        patch.setattr(execution_module, "RECENT", 1)  # nothing recent to go back to: every step back scans
        _walk_and_return(program)


def _unsaved(roots: object, outside: object = ()) -> snapshot.Snapshot:
    raise snapshot.NotSnapshotted("cannot save the state of a test's object")


@property_test
@given(program=timed_programs())
def test_without_checkpoints_going_back_runs_again_from_the_start_to_the_same_states(program: Program) -> None:
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(snapshot, "take", _unsaved)
        _walk_and_return(program)


@property_test
@given(
    program=timed_programs(),
    forward=st.integers(min_value=0, max_value=10),
    back=st.integers(0, 5),
    spacing=CHECKPOINTING,
)
def test_a_session_that_steps_and_steps_back_ends_as_the_run_without_the_debugger(
    program: Program, forward: int, back: int, spacing: tuple[int, int, int]
) -> None:
    """However the session went back and forth, the run ends where, when and as an uninterrupted run does,
    and the console shows what that run printed, once."""
    note(program.source)
    expected = run_source(program.source, limits=Limits(until_ms=UNTIL_MS, max_wall_s=None))
    with pytest.MonkeyPatch.context() as patch, tempfile.TemporaryDirectory() as folder:
        _checkpointing(patch, *spacing)
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


PRINTS = """\
DIM i
FOR i = 1 TO 4
  PRINT i
  WAIT = 2
NEXT
"""


def _stepped_through(source: str, folder: Path, stops: int) -> tuple[Harness, list[tuple[object, ...]]]:
    """A harness paused at the last of ``stops`` stops of a walk by ``stepIn`` through ``source``, and the stops."""
    harness = Harness(source, folder)
    return harness, _forward(harness, stops)


def test_output_printed_between_a_checkpoint_and_the_point_gone_back_to_is_not_shown_again(tmp_path: Path) -> None:
    with pytest.MonkeyPatch.context() as patch:
        _checkpointing(patch, 1, 1, 3)  # a checkpoint before every tick: the re-runs start just before each PRINT
        harness, _ = _stepped_through(PRINTS, tmp_path, 14)  # to the last NEXT
        execution = harness.execution
        for _ in range(6):
            assert execution.point is not None
            execution.step_back(execution.point)
            assert harness.wait() == "step"
        while execution.point is not None:
            execution.resume(stepping.cont(execution.point.count))
            harness.wait()
    assert harness.printed.split() == ["1", "2", "3", "4"]


WAITS = """\
DIM a
WAIT = 5
a = 1
WAIT = 5
a = 2
"""


def test_a_scan_from_a_checkpoint_taken_while_a_wait_blocks_skips_its_retries(tmp_path: Path) -> None:
    """Stepping back over ``WAIT = 5`` lands where it was first tried, at the time it started (0 ms, then 5 ms),
    not at its retry when it ends: the checkpoint before that retry knows the WAIT was blocked."""
    with pytest.MonkeyPatch.context() as patch:
        _checkpointing(patch, 1, 1, 10)
        patch.setattr(execution_module, "RECENT", 1)  # every step back scans
        harness, forward = _stepped_through(WAITS, tmp_path, 5)
        execution = harness.execution
        lines_and_times = []
        while execution.point is not None and execution.point.count > 0:
            execution.step_back(execution.point)
            assert harness.wait() == "step"
            lines_and_times.append((harness.state()[0].pc, harness.state()[3]))
    assert [state[3] for state in forward] == [0, 0, 5, 5, 10]  # each stop's time: both WAITs passed by stepIn
    assert lines_and_times == [(3, 5), (2, 5), (1, 0), (0, 0)]


COUNTED = """\
DIM i
FOR i = 1 TO 6
  WAIT = 2
NEXT
"""


def test_going_back_takes_a_hit_count_back_with_the_run(tmp_path: Path) -> None:
    """A breakpoint that stops at its fourth hit (i = 4), stepped back from, stops there again going on: the count
    is what it was at the checkpoint the re-run started from, three hits, and counts on from there."""
    with pytest.MonkeyPatch.context() as patch:
        _checkpointing(patch, 1, 1, 3)
        harness = Harness(COUNTED, tmp_path)
        execution = harness.execution
        execution.breakpoints.replace("program", [{"line": 3, "hitCondition": "4"}])
        execution.start(stepping.cont(-1))
        stops = [harness.wait()]
        values = [harness.state()[1]]
        for command in ("back", "continue"):
            assert execution.point is not None
            if command == "back":
                execution.step_back(execution.point)
            else:
                execution.resume(stepping.cont(execution.point.count))
            stops.append(harness.wait())
            values.append(harness.state()[1])
        execution.terminate()
    assert stops == ["breakpoint", "step", "breakpoint"]
    assert values == [(4.0,), (3.0,), (4.0,)]  # i: at the fourth hit, at NEXT before it, at the fourth hit again


@property_test
@given(program=timed_programs(), spacing=CHECKPOINTING, lines=st.sets(st.integers(1, 40), min_size=1, max_size=4))
def test_reverse_continue_lands_on_each_earlier_hit_of_the_forward_walk(
    program: Program, spacing: tuple[int, int, int], lines: set[int]
) -> None:
    """From the last stop of a walk by ``stepIn`` (which stops at every statement tried afresh), each
    reverse-continue lands on the walk's previous stop at a breakpoint's statement, with its state, and at the
    entry when there is none: stretches that never passed a breakpoint are skipped, not the hits."""
    note(program.source)
    with pytest.MonkeyPatch.context() as patch, tempfile.TemporaryDirectory() as folder:
        _checkpointing(patch, *spacing)
        forward = _forward(Harness(program.source, Path(folder)), STOPS)
        harness = Harness(program.source, Path(folder))
        assert _forward(harness, len(forward)) == forward
        execution = harness.execution
        execution.breakpoints.replace("program", [{"line": line} for line in sorted(lines)])
        at_breakpoints = set(execution.breakpoints.by_pc)
        while execution.point is not None and execution.point.count > 0:
            at = execution.point
            earlier = [state for state in forward if state[0].count < at.count and state[0].pc in at_breakpoints]
            execution.reverse_continue(at)
            assert harness.wait() == ("breakpoint" if earlier else "entry")
            assert harness.state() == (earlier[-1] if earlier else forward[0])
        execution.terminate()
