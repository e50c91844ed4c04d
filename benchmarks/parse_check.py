"""CPU time of ``mintlang.parse`` and ``mintlang.check`` beside CPython's ``ast.parse``, each in a fresh process.

Run: ``.venv/bin/python benchmarks/parse_check.py [--lines 5000] [--repeat 11] [--names 500]``

Fair by construction (issue 14): every figure is measured in a process of its own, started for that
one measurement, so no side holds the other's caches or objects; both sides run with the cyclic
garbage collector off (``mintlang`` pauses it for its own work, so ``ast.parse`` gets the same), after
a ``gc.collect()``; only the operation is timed (CPU time of the process), not the interpreter's start
or the imports, and the ``mintlang`` process first checks a two-line program so the grammar tables and
the keyword database are loaded, as they are for any check after the first. The Mint program is
realistic and mostly distinct lines (``programs.mint_program`` with ``--names`` variables and arrays;
the share of distinct lines is printed); the Python file has the same line count and about as many
tokens (printed too). "warm" checks the same text a second time in the process of a cold check, as the
language server does when it re-checks a file: only the whole-application work is left.

Targets: a cold check within 1.5 times ``ast.parse`` (the goal is 1.0); MintMT's check within 10 % of
v4's on the same program (``programs.mintmt_program``).
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import tempfile
import tokenize
from collections.abc import Iterable
from io import StringIO
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))

from programs import mint_program, mintmt_program, python_program

from mintlang.syntax.lexer import lex
from mintlang.syntax.tokens import TRIVIA

# Each measurement: (what the process does before the timer, what is timed, what is timed again after).
_SETUP_AST = "import ast"
_SETUP_MINT = "import mintlang\nmintlang.check('DIM a\\nPRINT a\\n')"
_MEASURED = {
    "ast.parse (CPython, reference)": (_SETUP_AST, "ast.parse(text)", None),
    "mintlang.parse, cold": (_SETUP_MINT, "mintlang.parse(text)", None),
    "mintlang.check (parse + check), cold": (_SETUP_MINT, "mintlang.check(text)", "mintlang.check(text)"),
    "mintlang.check MintMT (same program), cold": (_SETUP_MINT, "mintlang.check(text, dialect='mintmt')", None),
}
_REFERENCE = "ast.parse (CPython, reference)"
_WARM = "mintlang.check (parse + check), warm"
_V4, _MINTMT = "mintlang.check (parse + check), cold", "mintlang.check MintMT (same program), cold"

_PROCESS = """
import gc, sys, time
{setup}
text = open(sys.argv[1], encoding="utf-8").read()
gc.collect()
gc.disable()
start = time.process_time()
{timed}
print(time.process_time() - start)
{again}
"""
_AGAIN = "start = time.process_time()\n{timed}\nprint(time.process_time() - start)"


def _measure(setup: str, timed: str, again: str | None, path: Path) -> list[float]:
    """CPU seconds of ``timed`` (and of ``again`` after it) in a fresh Python process reading ``path``."""
    code = _PROCESS.format(setup=setup, timed=timed, again=_AGAIN.format(timed=again) if again else "")
    done = subprocess.run([sys.executable, "-c", code, str(path)], capture_output=True, text=True, check=True)
    return [float(line) for line in done.stdout.split()]


def _python_tokens(text: str) -> int:
    layout = {tokenize.NL, tokenize.NEWLINE, tokenize.INDENT, tokenize.DEDENT, tokenize.COMMENT, tokenize.ENDMARKER}
    return sum(1 for token in tokenize.generate_tokens(StringIO(text).readline) if token.type not in layout)


def _mint_tokens(text: str) -> int:
    return sum(1 for token in lex(text).tokens if token.kind not in TRIVIA)


def _distinct(text: str) -> float:
    lines = [line.strip() for line in text.splitlines()]
    return len(set(lines)) / len(lines)


def _spread(values: Iterable[float]) -> str:
    values = list(values)
    return f"{statistics.median(values):.2f} ({min(values):.2f}-{max(values):.2f})"


def main() -> None:
    options = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    options.add_argument("--lines", type=int, default=5000)
    options.add_argument("--repeat", type=int, default=11)
    options.add_argument("--names", type=int, default=500, help="variables and arrays of both programs")
    arguments = options.parse_args()
    if arguments.lines < 2 * arguments.names + 12:  # the declarations would push the loop's header past the cut
        options.error(f"--lines {arguments.lines} leaves no room for the loop after --names {arguments.names}")
    mint = mint_program(arguments.lines, names=arguments.names)
    texts = {
        _REFERENCE: python_program(arguments.lines, names=arguments.names),
        "mint": mint,
        _MINTMT: mintmt_program(arguments.lines, names=arguments.names),
    }
    seconds: dict[str, list[float]] = {name: [] for name in [*_MEASURED, _WARM]}
    with tempfile.TemporaryDirectory() as folder:
        paths = {name: Path(folder) / f"{index}.txt" for index, name in enumerate(texts)}
        for name, path in paths.items():
            path.write_text(texts[name], encoding="utf-8")
        for _ in range(arguments.repeat):  # paired rounds: a busy moment slows both sides of a ratio alike
            for name, (setup, timed, again) in _MEASURED.items():
                path = paths[name] if name in (_REFERENCE, _MINTMT) else paths["mint"]
                cold, *warm = _measure(setup, timed, again, path)
                seconds[name].append(cold)
                if warm:
                    seconds[_WARM].append(warm[0])
    python = texts[_REFERENCE]
    print(
        f"{arguments.lines} lines: Mint {_distinct(mint):.0%} distinct lines, {_mint_tokens(mint)} tokens; "
        f"Python {_python_tokens(python)} tokens"
    )
    print(f"CPU time, each in a fresh process with the collector off; median (min-max) of {arguments.repeat} rounds")
    print(f"{'':44} {'ms':>8} {'lines/s':>10}  x ast.parse")
    reference = seconds[_REFERENCE]
    for name, values in seconds.items():
        median = statistics.median(values)
        ratios = (value / base for value, base in zip(values, reference, strict=True))
        print(f"{name:44} {median * 1000:8.1f} {arguments.lines / median:10.0f}  {_spread(ratios)}")
    over_v4 = (mt / v4 for mt, v4 in zip(seconds[_MINTMT], seconds[_V4], strict=True))
    print(f"MintMT check / v4 check of the same program: {_spread(over_v4)} (target at most 1.10)")
    print("target: a cold check within 1.5 times ast.parse (goal 1.0)")


if __name__ == "__main__":
    main()
