"""Lines per second of ``mintlang.parse`` and ``mintlang.check``, beside CPython's ``ast.parse``.

Run: ``.venv/bin/python benchmarks/parse_check.py [--lines 5000] [--repeat 7]``

Both are measured in the same run on sources of the same line count (see
``programs.py``). "cold" clears the per-line caches (lexed, parsed, indexed
and checked lines) before each repetition, as a fresh ``mint check`` process
sees them; "warm" keeps them, as the language server does when it re-checks
a file after an edit (here the same text, so only the whole-application work
is left). The target is a parse + check ratio of at most 2.0 against
``ast.parse``, cold. The MintMT row checks the same program written as MintMT
(``programs.mintmt_program``); its last line compares it with the v4 check of
the same round (target: within 10 %).
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

from programs import mint_program, mintmt_program, python_program

import mintlang


def _seconds(action: Callable[[], object]) -> float:
    start = time.perf_counter()
    action()
    return time.perf_counter() - start


def main() -> None:
    options = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    options.add_argument("--lines", type=int, default=5000)
    options.add_argument("--repeat", type=int, default=15)
    arguments = options.parse_args()
    mint, python = mint_program(arguments.lines), python_program(arguments.lines)
    mintmt = mintmt_program(arguments.lines)
    mintlang.check(mint)  # build the grammar and load the keyword database once
    mintlang.check(mintmt, dialect="mintmt")

    def cold(action: Callable[[], object]) -> Callable[[], object]:
        def run() -> object:
            mintlang.clear_caches()
            return action()

        return run

    measured: dict[str, Callable[[], object]] = {
        "ast.parse (CPython, reference)": lambda: ast.parse(python),
        "mintlang.parse, cold": cold(lambda: mintlang.parse(mint)),
        "mintlang.check (parse + check), cold": cold(lambda: mintlang.check(mint)),
        "mintlang.check (parse + check), warm": lambda: mintlang.check(mint),
        "mintlang.check MintMT (same program), cold": cold(lambda: mintlang.check(mintmt, dialect="mintmt")),
    }
    v4_check, mintmt_check = "mintlang.check (parse + check), cold", "mintlang.check MintMT (same program), cold"
    # Paired rounds: each round times the reference and every variant back to back, so a
    # noisy machine slows both sides of a ratio alike; the medians of the per-round ratios
    # are reported.
    seconds: dict[str, list[float]] = {name: [] for name in measured}
    ratios: dict[str, list[float]] = {name: [] for name in measured}
    for _ in range(arguments.repeat):
        reference = _seconds(measured["ast.parse (CPython, reference)"])
        seconds["ast.parse (CPython, reference)"].append(reference)
        ratios["ast.parse (CPython, reference)"].append(1.0)
        for name, action in list(measured.items())[1:]:
            elapsed = _seconds(action)
            seconds[name].append(elapsed)
            ratios[name].append(elapsed / reference)
    print(f"{arguments.lines} lines, medians of {arguments.repeat} paired rounds")
    print(f"{'':44} {'ms':>8} {'lines/s':>10} {'x ast.parse':>12}")
    for name in measured:
        median = statistics.median(seconds[name])
        ratio = statistics.median(ratios[name])
        print(f"{name:44} {median * 1000:8.1f} {arguments.lines / median:10.0f} {ratio:12.2f}")
    mintmt_over_v4 = [mt / v4 for mt, v4 in zip(seconds[mintmt_check], seconds[v4_check], strict=True)]
    spread = f"{min(mintmt_over_v4):.2f}-{max(mintmt_over_v4):.2f}"
    print(f"MintMT check / v4 check of the same program: {statistics.median(mintmt_over_v4):.2f} ({spread})")


if __name__ == "__main__":
    main()
