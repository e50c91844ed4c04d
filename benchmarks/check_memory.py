"""Peak memory of ``mint check`` beside the input's size and beside a check of an empty file.

Run: ``.venv/bin/python benchmarks/check_memory.py [--repeat 3]``

Each input is checked by ``mint check`` in a fresh process, as a user or CI runs
it (text report to a pipe), and its peak resident set size is read from the
kernel (``wait4``). A process that imports the tool and checks a program takes
tens of megabytes whatever the input: the interpreter, the grammar tables, the
keyword database, and once it has something to report, the report's modules
(rich among them). That fixed cost is measured in the same round, under the
same conditions, as the check of a two-line program with one finding, and the
target (within 50 times the input) is read on what a check adds to it:
(peak - baseline) / input. An empty file is measured too: it reports nothing,
so it loads about a megabyte less, and would count that megabyte as the input's. A second figure is the peak that
``tracemalloc`` traces during ``mintlang.check`` alone, in a fresh process with
the grammar loaded and the per-line caches empty, over the input.

The inputs: ``programs.mint_program`` of about 0.1, 1 and 4 MB, with a variable
for every ten lines so that most lines are distinct (no per-line cache flatters
them); a 4 MB line of one long sum; and about 1 MB of broken lines (each line of
a program cut at a random place and closed by a stray ``)``, so each has a syntax error of its own).
Figures are medians with the min-max of the rounds.
"""

from __future__ import annotations

import argparse
import os
import random
import statistics
import subprocess
import sys
import tempfile
import tracemalloc
from collections.abc import Callable
from pathlib import Path

MINT = Path(sys.executable).parent / "mint"
_NAMES_MAX = 9_999  # speed9999, target9999: beyond, names equal in their first ten characters (W108)


def realistic(size: int) -> str:
    """A generated program of about ``size`` bytes, most of its lines distinct."""
    sys.path.insert(0, str(Path(__file__).parent))
    from programs import mint_program  # noqa: PLC0415  (in the process that writes the inputs only)

    sample = mint_program(1000, names=100)
    lines = round(1000 * size / len(sample))
    return mint_program(lines, names=min(lines // 10, _NAMES_MAX))


def one_line(size: int) -> str:
    """A program whose second line is a sum of ``size`` bytes."""
    return "DIM a\na = " + " + ".join(["1"] * (size // 4)) + "\nPRINT a\n"


def broken(size: int, seed: int = 17) -> str:
    """About ``size`` bytes of program lines, each cut at a random place and closed by a stray ``)``."""
    rng = random.Random(seed)
    lines = realistic(size).splitlines()
    return "".join(f"{line[: rng.randint(1, len(line))]} )\n" if line else "\n" for line in lines)


INPUTS: dict[str, Callable[[], str]] = {
    "program 0.1 MB": lambda: realistic(100_000),
    "program 1 MB": lambda: realistic(1_000_000),
    "program 4 MB": lambda: realistic(4_000_000),
    "one line 4 MB": lambda: one_line(4_000_000),
    "broken lines 1 MB": lambda: broken(1_000_000),
}


def peak_rss(path: Path) -> int:
    """The peak resident set size, in bytes, of a ``mint check`` of ``path`` in a process of its own."""
    process = subprocess.Popen([MINT, "check", str(path)], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(process.pid, 0)
    process.returncode = os.waitstatus_to_exitcode(status)
    if process.returncode not in (0, 1):
        raise SystemExit(f"mint check {path} exited with {process.returncode}")
    return usage.ru_maxrss * 1024  # kilobytes on Linux


def traced_peak(path: Path) -> int:
    """The peak ``tracemalloc`` traces during ``mintlang.check`` of ``path``, in a fresh process."""
    command = [sys.executable, __file__, "--traced", str(path)]
    return int(subprocess.run(command, capture_output=True, text=True, check=True).stdout)


def _traced(path: Path) -> int:
    import mintlang  # noqa: PLC0415  (in a process of its own: the one that measures RSS stays small)

    text = path.read_text(encoding="utf-8")
    mintlang.check("DIM a\na = 1\n")  # the grammar and the keyword database, loaded before tracing
    mintlang.clear_caches()
    tracemalloc.start()
    mintlang.check(text)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    return peak


def _spread(values: list[float], digits: int = 0) -> str:
    return f"{statistics.median(values):.{digits}f} ({min(values):.{digits}f}-{max(values):.{digits}f})"


def main() -> None:
    options = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    options.add_argument("--repeat", type=int, default=3)
    options.add_argument("--traced", type=Path, help=argparse.SUPPRESS)
    options.add_argument("--write", type=Path, help=argparse.SUPPRESS)
    arguments = options.parse_args()
    if arguments.traced:
        print(_traced(arguments.traced))
        return
    if arguments.write:
        for number, make in enumerate(INPUTS.values()):
            (arguments.write / f"{number}.mnt").write_text(make(), encoding="utf-8")
        return
    with tempfile.TemporaryDirectory() as folder:
        # The kernel's peak of a process counts from its fork, while it is still a copy of
        # this one: this process generates nothing and imports no mintlang, so it stays small.
        subprocess.run([sys.executable, __file__, "--write", folder], check=True)
        empty = Path(folder) / "empty.mnt"
        empty.write_text("", encoding="utf-8")
        smallest = Path(folder) / "one_finding.mnt"
        smallest.write_text("DIM a\nb = 1\n", encoding="utf-8")  # b is undeclared: E3001, so a report is written
        files = {name: Path(folder) / f"{number}.mnt" for number, name in enumerate(INPUTS)}
        empties: list[float] = []
        baseline: list[float] = []
        peaks: dict[str, list[float]] = {name: [] for name in files}
        ratios: dict[str, list[float]] = {name: [] for name in files}
        for _ in range(arguments.repeat):  # paired rounds: each round measures its own baseline
            empties.append(peak_rss(empty) / 1e6)
            baseline.append(peak_rss(smallest) / 1e6)
            for name, path in files.items():
                peaks[name].append(peak_rss(path) / 1e6)
                ratios[name].append((peaks[name][-1] - baseline[-1]) * 1e6 / path.stat().st_size)
        traced = {name: traced_peak(path) / path.stat().st_size for name, path in files.items()}
        sizes = {name: path.stat().st_size / 1e6 for name, path in files.items()}
    rounds = f"median (min-max) of {arguments.repeat} rounds"
    print(f"mint check, peak RSS in MB, {rounds}; target: (peak - baseline) within 50x the input")
    print(f"{'empty file':22} {'':>8} {_spread(empties):>16}")
    print(f"{'one finding (baseline)':22} {'':>8} {_spread(baseline):>16}")
    print(f"{'':22} {'input MB':>8} {'peak RSS MB':>16} {'(peak-base)/input':>20} {'traced/input':>13}")
    for name in files:
        print(
            f"{name:22} {sizes[name]:8.2f} {_spread(peaks[name]):>16} {_spread(ratios[name]) + 'x':>20}"
            f" {traced[name]:12.0f}x"
        )


if __name__ == "__main__":
    main()
