"""Start-up of the command-line tools: CPU time of each, beside ``python -c pass`` in the same run.

Run: ``.venv/bin/python benchmarks/startup.py [--repeat 21] [--phases]``

Each round runs the reference (``python -c pass``) and every command once, each in a
fresh process, back to back; the figures are the processes' CPU time (user + system,
from ``getrusage``), medians with the min–max of the rounds, and each command's
ratio to the reference is the median of its per-round ratios. Issue 14's target:
``mint check`` of a one-line file, ``mint-run`` and ``mint-migrate`` within 3 times
the reference.

The processes read compiled bytecode, as an installed package does (pip compiles it at
install time): the bytecode goes to a temporary folder (``PYTHONPYCACHEPREFIX``), and
one untimed round writes it first.

``--phases`` also says where the time of a one-line check goes: a fresh process takes
the steps of ``mint check`` one after the other (the modules of each step, then its
work) and times each; the last row is what the process spends beyond them (exiting,
mostly), so that the rows add up to about the ``mint check`` row. The text report into
a pipe needs no rich, so the steps leave it out too.
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

_SCRIPTS = Path(sys.executable).parent
_ONE_LINE = "SPEED = 10\n"
_TINY = 'DIM count = 2\nPRINT "count: ", count * 3\n'
_TINY_V3 = "SPEED = 10\nHMSPEED.0 = 10\n"  # HMSPEED is HOMESPEED in v4, and v4 needs an AXES line


def commands(folder: Path) -> dict[str, list[str | Path]]:
    """The commands timed, the reference first, with the programs they read written in ``folder``."""
    programs = {"one_line.mnt": _ONE_LINE, "tiny.mnt": _TINY, "tiny_v3.mnt": _TINY_V3}
    for name, text in programs.items():
        (folder / name).write_text(text, encoding="utf-8")
    return {
        "python -c pass (reference)": [sys.executable, "-c", "pass"],
        "mint --version": [_SCRIPTS / "mint", "--version"],
        "mint check, one-line file": [_SCRIPTS / "mint", "check", folder / "one_line.mnt"],
        "mint-run, tiny program": [_SCRIPTS / "mint-run", folder / "tiny.mnt"],
        "mint-migrate, tiny v3 program": [_SCRIPTS / "mint-migrate", folder / "tiny_v3.mnt"],
        "mint-run --version": [_SCRIPTS / "mint-run", "--version"],
        "mint-migrate --help": [_SCRIPTS / "mint-migrate", "--help"],
        "mint-lsp --version": [_SCRIPTS / "mint-lsp", "--version"],
    }


# The steps of a one-line ``mint check``, each timed after those before it in one fresh process.
_PHASES = """
import sys, time
marks = [("interpreter start-up (site, the editable install's finder)", time.process_time())]
def step(name):
    marks.append((name, time.process_time()))
import click; step("click")
import mintlang.cli.check; step("mint check's command line: settings, files, report (mintlang.cli.check)")
import mintlang.syntax.lark_runtime; step("lark's stand-alone runtime")
import mintlang.syntax.parser; step("the parser's modules (syntax nodes, lexer, builders)")
import mintlang.keyworddb; mintlang.keyworddb.database(); step("the keyword database loaded")
mintlang.parse("SPEED = 10"); step("first parse: LALR tables loaded, the line lexed and parsed")
import mintlang.analysis.analyser; step("the checker's modules (semantic model, rules)")
mintlang.check("SPEED = 10"); step("the check of the line")
from mintlang.allocation import no_collection_at_exit  # as the tools do
no_collection_at_exit()
previous = 0.0
for name, seconds in marks:
    print(f"{seconds - previous}\t{name}")
    previous = seconds
"""


def phases(repeat: int, environment: dict[str, str]) -> None:
    """Median (min-max) CPU ms of each step of a one-line check, over ``repeat`` fresh processes."""
    runs: list[list[tuple[float, str]]] = []
    for _ in range(repeat + 1):  # the first run is left out: the bytecode of a module it alone imports is written
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        output = subprocess.run(
            [sys.executable, "-c", _PHASES], capture_output=True, text=True, env=environment, check=True
        )
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        steps = [(float(seconds), name) for seconds, name in (line.split("\t") for line in output.stdout.splitlines())]
        total = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        runs.append([*steps, (total - sum(seconds for seconds, _ in steps), "the rest: exiting, mostly")])
    print(f"\nWhere a one-line mint check spends its CPU time, medians (min-max) of {repeat} fresh processes (ms)")
    for index, (_, name) in enumerate(runs[0]):
        print(f"{_spread([run[index][0] for run in runs[1:]], 1000):>20}  {name}")


def cpu_seconds(command: list[str | Path], environment: dict[str, str]) -> float:
    """User + system CPU time of one run of ``command`` in a fresh process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    result = subprocess.run(command, capture_output=True, env=environment, check=False)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if result.returncode != 0:
        raise SystemExit(f"{command} failed ({result.returncode}):\n{result.stderr.decode()}")
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def _spread(values: list[float], scale: float = 1.0, digits: int = 1) -> str:
    scaled = [value * scale for value in values]
    return f"{statistics.median(scaled):.{digits}f} ({min(scaled):.{digits}f}-{max(scaled):.{digits}f})"


def main() -> None:
    options = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    options.add_argument("--repeat", type=int, default=21)
    options.add_argument("--phases", action="store_true", help="Also time the steps of a one-line check.")
    arguments = options.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        environment = {key: value for key, value in os.environ.items() if key != "PYTHONDONTWRITEBYTECODE"}
        environment |= {"PYTHONPYCACHEPREFIX": str(Path(folder) / "bytecode"), "NO_COLOR": "1"}
        timed = commands(Path(folder))
        for command in timed.values():  # writes the bytecode
            cpu_seconds(command, environment)
        seconds: dict[str, list[float]] = {name: [] for name in timed}
        for _ in range(arguments.repeat):
            for name, command in timed.items():
                seconds[name].append(cpu_seconds(command, environment))
        reference = seconds["python -c pass (reference)"]
        print(f"CPU time of a fresh process, medians (min-max) of {arguments.repeat} paired rounds")
        print(f"{'':32} {'ms':>20} {'x python -c pass':>20}")
        for name, values in seconds.items():
            ratios = [value / base for value, base in zip(values, reference, strict=True)]
            print(f"{name:32} {_spread(values, 1000):>20} {_spread(ratios):>20}")
        if arguments.phases:
            phases(arguments.repeat, environment)


if __name__ == "__main__":
    main()
