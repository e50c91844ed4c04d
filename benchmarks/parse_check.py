"""Lines per second of ``mintlang.parse`` and ``mintlang.check``, beside CPython's ``ast.parse``.

Run: ``.venv/bin/python benchmarks/parse_check.py [--lines 5000] [--repeat 7]``

Both are measured in the same run on sources of the same line count (see
``programs.py``). "cold" clears the lexer's and parser's caches before each
repetition, as a fresh ``mint check`` process sees them; "warm" keeps them,
as the language server does when it re-checks a file after an edit. The
target is a parse + check ratio of at most 2.0 against ``ast.parse``.
"""

from __future__ import annotations

import argparse
import ast
import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))

from programs import mint_program, python_program

import mintlang
from mintlang.syntax.parser import clear_caches


def _median_seconds(action: Callable[[], object], repeat: int, before: Callable[[], None] | None = None) -> float:
    times = []
    for _ in range(repeat):
        if before is not None:
            before()
        start = time.perf_counter()
        action()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main() -> None:
    options = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    options.add_argument("--lines", type=int, default=5000)
    options.add_argument("--repeat", type=int, default=7)
    arguments = options.parse_args()
    mint, python = mint_program(arguments.lines), python_program(arguments.lines)
    mintlang.check(mint)  # build the grammar and load the keyword database once

    reference = _median_seconds(lambda: ast.parse(python), arguments.repeat)
    rows = [
        ("ast.parse (CPython, reference)", reference),
        ("mintlang.parse, cold", _median_seconds(lambda: mintlang.parse(mint), arguments.repeat, clear_caches)),
        (
            "mintlang.check (parse + check), cold",
            _median_seconds(lambda: mintlang.check(mint), arguments.repeat, clear_caches),
        ),
        ("mintlang.check (parse + check), warm", _median_seconds(lambda: mintlang.check(mint), arguments.repeat)),
    ]
    print(f"{arguments.lines} lines, median of {arguments.repeat} runs")
    print(f"{'':40} {'ms':>8} {'lines/s':>10} {'x ast.parse':>12}")
    for name, seconds in rows:
        print(f"{name:40} {seconds * 1000:8.1f} {arguments.lines / seconds:10.0f} {seconds / reference:12.2f}")


if __name__ == "__main__":
    main()
