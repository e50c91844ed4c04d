"""Milliseconds per diagnostic of ``mint check``'s text report, beside its JSON report.

Run: ``.venv/bin/python benchmarks/check_output.py [--diagnostics 10000] [--repeat 15]``

Only the writing is timed: one program whose every line has an undeclared name
is checked once, outside the timing, and paired rounds then render its
diagnostics as text with colour (the escape codes of a 256-colour terminal), as
plain text (a pipe), and as JSON, the reference, back to back, into memory. Each
line names a different variable, so no two frames are alike. The figures are
medians with the min–max of the rounds. The target is at most 0.05 ms per
diagnostic in text.
"""

from __future__ import annotations

import argparse
import gc
import io
import statistics
import time
from collections.abc import Callable

from rich.console import Console

from mintlang import check_application
from mintlang.cli.report import FileReport, as_json, render_text


def _report(diagnostics: int) -> FileReport:
    source = "DIM gain\n" + "".join(f"PRINT rate{n} * 2, gain\n" for n in range(diagnostics))
    found = check_application(source).program
    assert len(found) == diagnostics, len(found)  # one undeclared name a line (gain is declared)
    return FileReport("benchmark.mnt", source, found)


def _text(report: FileReport, color_system: str | None) -> Callable[[], object]:
    def render() -> object:
        console = Console(file=io.StringIO(), color_system=color_system, force_terminal=color_system is not None)
        render_text([report], console.file, console)
        return console.file

    return render


def _seconds(action: Callable[[], object]) -> float:
    gc.collect()
    start = time.perf_counter()
    action()
    return time.perf_counter() - start


def main() -> None:
    options = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    options.add_argument("--diagnostics", type=int, default=10000)
    options.add_argument("--repeat", type=int, default=15)
    arguments = options.parse_args()
    report = _report(arguments.diagnostics)
    count = len(report.diagnostics)
    measured: dict[str, Callable[[], object]] = {
        "json (reference)": lambda: as_json([report]),
        "text, 256 colours": _text(report, "256"),
        "text, plain": _text(report, None),
    }
    seconds: dict[str, list[float]] = {name: [] for name in measured}
    for _ in range(arguments.repeat):
        for name, action in measured.items():
            seconds[name].append(_seconds(action))
    print(f"{count} diagnostics, medians (min-max) of {arguments.repeat} paired rounds")
    print(f"{'':20} {'ms/diagnostic':>24} {'x json':>8}")
    reference = statistics.median(seconds["json (reference)"])
    for name, values in seconds.items():
        per = [value / count * 1000 for value in values]
        spread = f"{statistics.median(per):.4f} ({min(per):.4f}-{max(per):.4f})"
        print(f"{name:20} {spread:>24} {statistics.median(values) / reference:8.2f}")


if __name__ == "__main__":
    main()
