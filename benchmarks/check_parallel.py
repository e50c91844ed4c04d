"""Wall time of ``mint check -j`` on a directory of 500 programs, beside ``-j 1`` in the same run.

Run: ``.venv/bin/python benchmarks/check_parallel.py [--files 500] [--lines 200] [--repeat 5]``

The programs are ``programs.mint_program`` texts with a seed of their own each,
so their lines are mostly distinct and no per-line cache flatters either side.
Each round runs ``mint check --format json`` in a fresh process twice, back to
back: with one process (the reference) and with all cores (``-j 0``, the
default). The figures are medians with the min–max of the rounds, and the
speed-up is the median of the per-round ratios; the CPU time of each run (all
its processes) shows what the workers cost beyond the single process.
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))

from programs import mint_program

from mintlang.cli.parallel import all_cores

MINT = Path(sys.executable).parent / "mint"


def _run(directory: Path, jobs: int) -> tuple[float, float]:
    """Wall and CPU seconds of one ``mint check`` of ``directory``."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    result = subprocess.run(
        [MINT, "check", "--format", "json", "-j", str(jobs), directory], capture_output=True, check=False
    )
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if result.returncode not in (0, 1):
        raise SystemExit(result.stderr.decode())
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main() -> None:
    options = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    options.add_argument("--files", type=int, default=500)
    options.add_argument("--lines", type=int, default=200)
    options.add_argument("--repeat", type=int, default=5)
    arguments = options.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        directory = Path(folder)
        for number in range(arguments.files):
            (directory / f"p{number:04}.mnt").write_text(mint_program(arguments.lines, seed=number), encoding="utf-8")
        runs = {"-j 1 (reference)": 1, f"-j 0 ({all_cores()} cores)": 0}
        wall: dict[str, list[float]] = {name: [] for name in runs}
        cpu: dict[str, list[float]] = {name: [] for name in runs}
        ratios: list[float] = []
        for _ in range(arguments.repeat):
            for name, jobs in runs.items():
                seconds, used = _run(directory, jobs)
                wall[name].append(seconds)
                cpu[name].append(used)
            ratios.append(wall["-j 1 (reference)"][-1] / seconds)
    print(f"{arguments.files} files of {arguments.lines} lines, medians (min-max) of {arguments.repeat} paired rounds")
    print(f"{'':22} {'wall s':>20} {'cpu s':>8}")
    for name in runs:
        spread = f"{statistics.median(wall[name]):.2f} ({min(wall[name]):.2f}-{max(wall[name]):.2f})"
        print(f"{name:22} {spread:>20} {statistics.median(cpu[name]):8.2f}")
    print(f"speed-up: {statistics.median(ratios):.2f} ({min(ratios):.2f}-{max(ratios):.2f}) on {os.cpu_count()} CPUs")


if __name__ == "__main__":
    main()
