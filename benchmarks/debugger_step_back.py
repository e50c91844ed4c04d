"""How long ``mint-dap`` takes to step back, beside an uninterrupted run of the same program.

Run: ``.venv/bin/python benchmarks/debugger_step_back.py [--cycles 600] [--repeat 5]``

The program is a machine cycle (a move, a wait for it, a dwell) repeated
``--cycles`` times, about one simulated second each: 600 cycles are the ten
simulated minutes issue 15 names. Each round, paired:

- reference: ``run_source`` of the program, start to end, with no debugger;
- forward: the same under the debugger, to a breakpoint on its last statement;
- step back: the debugger, paused at the program's last statement, steps back one statement;
- reverse-continue: from there, back to the last hit of a breakpoint in the loop.

Going back re-runs the program from its start (``runtime/debugger/history.py``), twice: a scan
that finds the earlier point, then a run that stops there. Figures are wall seconds, medians
(min-max) over the rounds, and each median over the reference's.
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import threading
import time
from collections.abc import Callable
from pathlib import Path

from mintlang.runtime.debugger import stepping
from mintlang.runtime.debugger.breakpoints import Breakpoints
from mintlang.runtime.debugger.execution import Execution
from mintlang.runtime.debugger.launch import Application, layout, prepare
from mintlang.runtime.run import RunResult, run_source
from mintlang.runtime.scenario.stimulus import DrivesEnabled, Scenario
from mintlang.runtime.simulation import Limits

LOOP_LINE = 7  # cycles = cycles + 1: the breakpoint reverse-continue goes back to


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


def round_trip(application: Application, last_line: int) -> tuple[float, float, float]:
    """(forward to the last statement, step back, reverse-continue), in seconds."""
    arrivals = Arrivals()
    breakpoints = Breakpoints(layout(application))
    execution = Execution(application, breakpoints, arrivals)
    breakpoints.replace("program", [{"line": last_line}])
    forward = timed(arrivals, lambda: execution.start(stepping.cont(-1)))
    breakpoints.replace("program", [{"line": LOOP_LINE}])
    at_end = execution.point
    assert at_end is not None
    back = timed(arrivals, lambda: execution.step_back(at_end))
    one_back = execution.point
    assert one_back is not None
    reverse = timed(arrivals, lambda: execution.reverse_continue(one_back))
    execution.terminate()
    return forward, back, reverse


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cycles", type=int, default=600)
    parser.add_argument("--repeat", type=int, default=5)
    options = parser.parse_args()
    source = program(options.cycles)
    names = ("reference (no debugger)", "forward (debugger)", "step back", "reverse-continue")
    rows: dict[str, list[float]] = {name: [] for name in names}
    simulated_ms = 0
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "cycle.mnt"
        path.write_text(source, encoding="utf-8")
        application = prepare({"program": str(path), "drives": "enabled", "dialect": "v4", "noConfig": True})
        for _ in range(options.repeat):
            began = time.perf_counter()
            result = run_source(source, scenario=Scenario(drives=(DrivesEnabled(),)), limits=Limits(max_wall_s=None))
            rows["reference (no debugger)"].append(time.perf_counter() - began)
            simulated_ms = result.stop.time_ms
            for name, seconds in zip(list(rows)[1:], round_trip(application, source.count("\n")), strict=True):
                rows[name].append(seconds)
    simulated_s = simulated_ms / 1000
    print(f"{options.cycles} cycles, {simulated_s:.0f} simulated s; medians (min-max) of {options.repeat} rounds")
    reference = statistics.median(rows["reference (no debugger)"])
    print(f"{'':26}{'wall s':>24}{'x reference':>14}")
    for name, times in rows.items():
        median = statistics.median(times)
        print(f"{name:26}{f'{median:.3f} ({min(times):.3f}-{max(times):.3f})':>24}{median / reference:>14.2f}")


if __name__ == "__main__":
    main()
