"""How long ``mint-dap`` takes to step back, beside an uninterrupted run of the same program.

Run: ``.venv/bin/python benchmarks/debugger_step_back.py [--cycles 600] [--repeat 5]``

The program is a machine cycle (a move, a wait for it, a dwell) repeated
``--cycles`` times, about one simulated second each: 600 cycles are the ten
simulated minutes issue 15 names. Each round, paired:

- reference: ``run_source`` of the program, start to end, with no debugger;
- forward: the same under the debugger, to a breakpoint on its last statement;
- step back: the debugger, paused at the program's last statement, steps back one statement;
- reverse-continue: from there, back to the last hit of a breakpoint in the loop;
- reverse-continue to the start: from there, back to a breakpoint before the loop, across the ten
  minutes (the stretches between checkpoints that never passed its statement are skipped);
- forward, no checkpoints: forward again with checkpoints turned off, what they cost it.

Going back restores the latest checkpoint before the point and runs on from it
(``runtime/debugger/checkpoints.py``). Figures are wall seconds, medians (min-max) over the
rounds, and each median over the reference's. Then the checkpoints the forward run kept, the
memory one holds, and the time to save and restore the simulation's state, beside
``copy.deepcopy`` of it (which would not even be a working copy: the copied controller's
closures still drive the original).
"""

from __future__ import annotations

import argparse
import copy
import statistics
import tempfile
import threading
import time
import tracemalloc
from collections.abc import Callable
from pathlib import Path
from unittest import mock

from mintlang.runtime import snapshot
from mintlang.runtime.debugger import stepping
from mintlang.runtime.debugger.breakpoints import Breakpoints
from mintlang.runtime.debugger.execution import Execution
from mintlang.runtime.debugger.launch import Application, layout, prepare
from mintlang.runtime.run import RunResult, run_source
from mintlang.runtime.scenario.stimulus import DrivesEnabled, Scenario
from mintlang.runtime.simulation import Limits, Simulator

LOOP_LINE = 7  # cycles = cycles + 1: the breakpoint reverse-continue goes back to
START_LINE = 2  # DIM cycles: the breakpoint before the loop
SAVES = 50  # snapshots timed, each way


def program(cycles: int) -> str:
    return f"""DIM n
DIM cycles
FOR n = 1 TO {cycles}
  MOVER.0 = 10 : GO.0
  PAUSE IDLE.0
  WAIT = 990
  cycles = cycles + 1
NEXT
PRINT cycles
"""


class Arrivals:
    """The debugger's listener: each stop (or the end) sets ``arrived``."""

    def __init__(self) -> None:
        self.arrived = threading.Event()

    def stopped(self, reason: str, description: str | None) -> None:
        self.arrived.set()

    def output(self, text: str, category: str) -> None:
        pass

    def finished(self, result: RunResult | None, problem: str | None) -> None:
        self.arrived.set()


def timed(arrivals: Arrivals, action: Callable[[], None]) -> float:
    """Wall seconds from ``action`` to the stop it leads to."""
    arrivals.arrived.clear()
    began = time.perf_counter()
    action()
    arrivals.arrived.wait()
    return time.perf_counter() - began


def round_trip(application: Application, last_line: int) -> tuple[tuple[float, ...], int]:
    """(forward to the last statement, step back, reverse-continue, reverse-continue to the start), in seconds,
    and the checkpoints kept."""
    arrivals = Arrivals()
    breakpoints = Breakpoints(layout(application))
    execution = Execution(application, breakpoints, arrivals)
    breakpoints.replace("program", [{"line": last_line}])
    forward = timed(arrivals, lambda: execution.start(stepping.cont(-1)))
    kept = execution.checkpoints_kept
    breakpoints.replace("program", [{"line": LOOP_LINE}])
    at_end = execution.point
    assert at_end is not None
    back = timed(arrivals, lambda: execution.step_back(at_end))
    one_back = execution.point
    assert one_back is not None
    reverse = timed(arrivals, lambda: execution.reverse_continue(one_back))
    breakpoints.replace("program", [{"line": START_LINE}])
    in_loop = execution.point
    assert in_loop is not None
    to_start = timed(arrivals, lambda: execution.reverse_continue(in_loop))
    assert execution.point is not None and execution.point.count < one_back.count
    execution.terminate()
    return (forward, back, reverse, to_start), kept


def _unsaved(roots: object, outside: object = ()) -> snapshot.Snapshot:
    raise snapshot.NotSnapshotted("checkpoints turned off for the benchmark")


def forward_without_checkpoints(application: Application, last_line: int) -> float:
    """Forward to the last statement with no checkpoint taken (the debugger falls back to none), in seconds."""
    arrivals = Arrivals()
    breakpoints = Breakpoints(layout(application))
    execution = Execution(application, breakpoints, arrivals)
    breakpoints.replace("program", [{"line": last_line}])
    with mock.patch.object(snapshot, "take", _unsaved):
        forward = timed(arrivals, lambda: execution.start(stepping.cont(-1)))
    execution.terminate()
    return forward


def saving(source: str) -> tuple[int, float, float, float]:
    """(bytes one snapshot holds, ms to take one, to restore one, to ``copy.deepcopy`` the state), halfway."""
    found: list[tuple[int, float, float, float]] = []

    def halfway(simulator: Simulator) -> None:
        def before_tick(tick: int) -> None:
            if tick < 300_000 or found:
                return
            taken = snapshot.take([simulator])  # the first also fills the walk's caches: not counted
            tracemalloc.start()
            kept = [snapshot.take([simulator]) for _ in range(10)]
            size = tracemalloc.get_traced_memory()[0] // len(kept)
            tracemalloc.stop()
            began = time.perf_counter()
            for _ in range(SAVES):
                snapshot.take([simulator])
            take = (time.perf_counter() - began) / SAVES * 1000
            began = time.perf_counter()
            for _ in range(SAVES):
                taken.restore()
            restore = (time.perf_counter() - began) / SAVES * 1000
            began = time.perf_counter()
            for _ in range(SAVES):
                copy.deepcopy(simulator)
            deep = (time.perf_counter() - began) / SAVES * 1000
            found.append((size, take, restore, deep))

        simulator.before_tick = before_tick

    limits = Limits(max_wall_s=None, program_alone=False)
    run_source(source, scenario=Scenario(drives=(DrivesEnabled(),)), limits=limits, on_simulator=halfway)
    return found[0]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cycles", type=int, default=600)
    parser.add_argument("--repeat", type=int, default=5)
    options = parser.parse_args()
    source = program(options.cycles)
    names = ("reference (no debugger)", "forward (debugger)", "step back", "reverse-continue")
    names += ("reverse-continue to start", "forward, no checkpoints")
    rows: dict[str, list[float]] = {name: [] for name in names}
    simulated_ms = 0
    kept = 0
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "cycle.mnt"
        path.write_text(source, encoding="utf-8")
        application = prepare({"program": str(path), "drives": "enabled", "dialect": "v4", "noConfig": True})
        for _ in range(options.repeat):
            began = time.perf_counter()
            result = run_source(source, scenario=Scenario(drives=(DrivesEnabled(),)), limits=Limits(max_wall_s=None))
            rows["reference (no debugger)"].append(time.perf_counter() - began)
            simulated_ms = result.stop.time_ms
            times, kept = round_trip(application, source.count("\n"))
            times += (forward_without_checkpoints(application, source.count("\n")),)
            for name, seconds in zip(list(rows)[1:], times, strict=True):
                rows[name].append(seconds)
    simulated_s = simulated_ms / 1000
    print(f"{options.cycles} cycles, {simulated_s:.0f} simulated s; medians (min-max) of {options.repeat} rounds")
    reference = statistics.median(rows["reference (no debugger)"])
    print(f"{'':26}{'wall s':>24}{'x reference':>14}")
    for name, times in rows.items():
        median = statistics.median(times)
        print(f"{name:26}{f'{median:.3f} ({min(times):.3f}-{max(times):.3f})':>24}{median / reference:>14.2f}")
    size, take, restore, deep = saving(source)
    print(f"checkpoints kept after the forward run: {kept}; one holds {size / 1000:.0f} kB")
    print(f"saving the state {take:.2f} ms, restoring it {restore:.2f} ms; copy.deepcopy of it {deep:.2f} ms")


if __name__ == "__main__":
    main()
