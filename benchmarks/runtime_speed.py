"""Simulated seconds per wall second of ``mint-run`` on a 4-axis program that moves all the time.

Run: ``.venv/bin/python benchmarks/runtime_speed.py [--ideal-s 600] [--torque-s 20] [--repeat 3]
[--loop-n 200000] [--loop-repeat 7]``

The same program runs with every axis on the ideal plant (the default) and on
the torque-amplifier plant (inertia and friction driven through PIDVFA, so the
servo loop and the plant are integrated on every 1 ms tick). The figure is
simulated time over wall time, measured in the same run as the reference
(real time = 1x). Targets: ≥ 1000x with the ideal plant, ≥ 50x with the torque plant.

Then it prints the interpreter's figure (``interpreter_speed.py``): statements
per second of a tight arithmetic loop beside CPython running the same loop in
the same run (``--loop-n 0`` leaves it out).
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

from mintlang.runtime.motion.plants import TORQUE_PLANT_GAINS
from mintlang.runtime.run import run_source
from mintlang.runtime.scenario.stimulus import PlantChoice, Scenario
from mintlang.runtime.simulation import Limits

sys.path.insert(0, str(Path(__file__).parent))

import interpreter_speed

AXES = (0, 1, 2, 3)
CONFIGURATION = "RESET[0,1,2,3]\n"
PROGRAM = """AXES[0,1,2,3]
LOOP
  MOVER = 4000, 3000, 2000, 1000
  GO
  PAUSE IDLE[0,1,2,3]
  MOVER = -4000, -3000, -2000, -1000
  GO
  PAUSE IDLE[0,1,2,3]
ENDL
"""


def _gains() -> str:
    g = TORQUE_PLANT_GAINS
    return (
        f"KPROP = {g.kprop};\nKDERIV = {g.kderiv};\nKVELFF = {g.kvelff};\nKACCEL = {g.kaccel};\n" if g.kint == 0 else ""
    )


def _speed(simulated_s: float, scenario: Scenario, configuration: str) -> float:
    limits = Limits(until_ms=int(simulated_s * 1000), max_wall_s=600.0)
    # a short run first, so the parser's one-off grammar construction is not counted as simulation
    run_source(PROGRAM, config=configuration, controller="nextmove-bx", scenario=scenario, limits=Limits(until_ms=2))
    start = time.perf_counter()
    result = run_source(PROGRAM, config=configuration, controller="nextmove-bx", scenario=scenario, limits=limits)
    elapsed = time.perf_counter() - start
    if result.stop.reason.value != "until" or any(axis.axiserror for axis in result.axes[:4]):
        raise SystemExit(f"the benchmark program did not run cleanly: {result.stop}")
    return simulated_s / elapsed


def main() -> None:
    options = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    options.add_argument("--ideal-s", type=float, default=600.0, help="simulated seconds with the ideal plant")
    options.add_argument("--torque-s", type=float, default=20.0, help="simulated seconds with the torque plant")
    options.add_argument("--repeat", type=int, default=3)
    options.add_argument("--loop-n", type=int, default=200_000, help="passes of the interpreter's loops (0: skip)")
    options.add_argument("--loop-repeat", type=int, default=7, help="paired rounds of the interpreter's loops")
    arguments = options.parse_args()
    torque = Scenario(plants=tuple(PlantChoice(axis, "torque") for axis in AXES))
    torque_configuration = CONFIGURATION + "AXES[0,1,2,3]\n" + _gains()
    ideal = [_speed(arguments.ideal_s, Scenario(), CONFIGURATION) for _ in range(arguments.repeat)]
    physical = [_speed(arguments.torque_s, torque, torque_configuration) for _ in range(arguments.repeat)]
    print("4-axis program moving continuously (median (min-max) of", arguments.repeat, "runs; real time = 1x)")
    print(
        f"  ideal plant : {statistics.median(ideal):8.0f}x real time ({min(ideal):.0f}-{max(ideal):.0f})"
        "   (target ≥ 1000x)"
    )
    print(
        f"  torque plant: {statistics.median(physical):8.1f}x real time ({min(physical):.1f}-{max(physical):.1f})"
        "   (target ≥ 50x)"
    )
    if arguments.loop_n > 0:
        print()
        interpreter_speed.report(arguments.loop_n, arguments.loop_repeat)


if __name__ == "__main__":
    main()
