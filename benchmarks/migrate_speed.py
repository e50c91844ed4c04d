"""Time and memory of ``mint-migrate`` beside ``mintlang.parse`` of the same v3 text.

Run: ``.venv/bin/python benchmarks/migrate_speed.py [SIZE ...] [--repeat 7]``, a size being
lines (``10000``) or megabytes (``1.4MB``); by default 1,000, 10,000 and 100,000 lines and 1.4 MB.

The program is what a v3 machine builder writes (the shapes of the v3 guide's
listings in ``tests/corpus/v3/programs``): a set-up of several axes with v3
keywords and abbreviations, homing, moves with I/O handshakes, jogging from an
analogue input, flying shears, a keypad menu, subroutines and an error handler.
Names and numbers vary from block to block, so most lines are distinct: per-line
caches do not flatter either side. A fixed seed makes it the same on every run.

Each size runs in a fresh process, as ``mint-migrate`` does: the grammars and the
keyword database are loaded once, outside the timing, then paired rounds time
``mintlang.migrate.migrate(text)`` and ``mintlang.parse(text, dialect="v3")``
back to back, both with the per-line caches cleared first (a fresh process has
them empty) and both pausing the garbage collector themselves. The figures are
medians with the min–max of the rounds, in wall time and in the process's CPU time
(on a machine shared with other jobs the second is the steadier). The target is a
migration within 3 times the parse. Memory is the peak traced by ``tracemalloc`` during one migration in
a process of its own, beside the input's size (target: within 50 times).
"""

from __future__ import annotations

import argparse
import json
import random
import statistics
import subprocess
import sys
import time
import tracemalloc
from collections.abc import Callable

import mintlang
from mintlang.migrate import migrate

_STEMS = ("pos", "speed", "count", "offset", "target", "length", "cut", "feed", "delay", "index", "step", "jog")
_TABLES = tuple(f"DIM table{n}({20 + n * 5})" for n in range(8))
_SUBROUTINES = 200  # at most about this many: with #sub0 and #ONERROR, within the 255 labels


def _name(rng: random.Random, i: int) -> str:
    """A variable: 240 names over the program, within what a v3 controller holds (255)."""
    return f"{rng.choice(_STEMS)}{(i * 7 + rng.randrange(40)) % 20}"


def _setup(rng: random.Random, i: int) -> list[str]:
    axis = i % 4
    return [
        f"REM axis {axis} set-up, station {i}",
        f"SCALE.{axis} = {rng.choice((500, 1000, 2000, 4000, 8192))}; : REM counts per unit",
        f"SPEED.{axis} = {rng.randint(5, 200)}",
        f"ACCEL.{axis} = {rng.randint(50, 5000)}",
        f"HMSPEED.{axis} = {rng.randint(1, 50)} : BACKOFF.{axis} = {rng.randint(1, 20)}",
        f"KVEL.{axis} = {rng.randint(0, 80)} : GAIN.{axis} = {rng.randint(1, 40)}.{rng.randint(0, 9)}",
        f"MFOLERR.{axis} = {rng.randint(1, 9)} : CURRLIMIT.{axis} = {rng.randint(20, 100)}",
        f"IDLE.{axis} = .{rng.randint(1, 99)} : HOME.{axis} = {rng.randint(0, 3)}",
        f"PAUSE IDLE.{axis} : REM homed {i}",
    ]


def _moves(rng: random.Random, i: int) -> list[str]:
    a, b = _name(rng, i), _name(rng, i + 1)
    return [
        f"  {a} = {rng.randint(1, 9999)}",
        f"  {b} = {a} * {rng.randint(2, 9)} / {rng.randint(2, 50)}",
        f"  MOVEA = {a}, {b} : GO : REM to point {i}",
        f"  PAUSE IDLE[0,1] : OUT{i % 8} = 1",
        f"  PAUSE IN{i % 16} : OUT{i % 8} = 0 : REM handshake {i}",
    ]


def _condition(rng: random.Random, i: int) -> list[str]:
    a = _name(rng, i)
    return [
        f"  IF IN{i % 16} AND {a} > {rng.randint(1, 500)} DO",
        f"    OUT{rng.randrange(8)} = _on : WAIT = {rng.randint(10, 900)}",
        f"    MR.{i % 3} = {a} - POS.{i % 3} : GO.{i % 3}",
        "  ELSE",
        f'    PRINT "station {i}: ", {a}, " at ", POS.{i % 3}',
        f"    JOG = {rng.randint(-90, 90)}, {rng.randint(-90, 90)}",
        f"  ENDIF : REM station {i}",
    ]


def _loop(rng: random.Random, i: int) -> list[str]:
    a, b = _name(rng, i), f"table{rng.randrange(len(_TABLES))}"
    return [
        f"  FOR {a} = 1 TO {rng.randint(2, 20)}",
        f"    VECTORA = {b}({a}), {rng.randint(0, 999)} : GO",
        f"    PAUSE IDLE[0,1] : REM point {i}",
        f"    {b}({a}) = POS[0] + {rng.randint(1, 99)}",
        "  NEXT",
    ]


def _joystick(rng: random.Random, i: int) -> list[str]:
    a = _name(rng, i)
    return [
        f"  REPEAT : REM jog {i} from the joystick",
        f"    {a} = ANALOGUE{1 + i % 3} - {rng.choice((511, 512, 500))}",
        f"    IF ABS({a}) < {rng.randint(2, 30)} THEN {a} = 0",
        f"    JOG.{i % 2} = {a} * {rng.randint(1, 9)}",
        f"  UNTIL INKEY = '{rng.choice('ABCDEF')}'",
        f"  STOP.{i % 2} : PAUSE IDLE.{i % 2}",
    ]


def _shear(rng: random.Random, i: int) -> list[str]:
    return [
        f"  MASTERINC = {rng.randint(100, 9000)} : REM accelerate, cut {i}",
        f"  FLY = {rng.randint(100, 9000)} : GO",
        f"  MASTERINC = {rng.randint(100, 9000)}",
        f"  FLY = {rng.randint(0, 99)} : GO",
        f"  GEARN = {rng.randint(1, 20)} : GEARD = {rng.randint(1, 20)}",
    ]


def _menu(rng: random.Random, i: int) -> list[str]:
    key = _name(rng, i)
    return [
        f'  LINE {1 + i % 4}, "menu {i}"',
        f"  WHILE {key} = 0",
        f"    {key} = INKEY : REM key {i}",
        f"    IF {key} = '{rng.choice('ABCD')}' THEN BEEP : GOSUB sub{rng.randrange(i)}",
        "  ENDW",
    ]


def _limits(rng: random.Random, i: int) -> list[str]:
    axis = i % 2
    return [
        f"  IF ERROR.{axis} = _limit DO : REM limit check {i}",
        f"    DISLIMIT.{axis} : SERVOFF.{axis}",
        f"    PAUSE !LIMIT.{axis} : WAIT = {rng.randint(10, 500)}",
        f"    SERVOC.{axis} : ENLIMIT.{axis}",
        "  ENDIF",
    ]


_BLOCKS: tuple[Callable[[random.Random, int], list[str]], ...] = (
    _moves,
    _condition,
    _loop,
    _joystick,
    _shear,
    _menu,
    _limits,
)


def v3_program(lines: int, seed: int = 1998) -> str:
    """A Mint v3 program of about ``lines`` lines: a main loop calling subroutines, each a few
    blocks; set-up blocks in the first subroutine. A larger program has longer subroutines,
    not more of them: the controller holds 255 labels (``mint check`` reports more as an error)."""
    rng = random.Random(seed)
    main = ["REM Generated v3 benchmark program", *_TABLES, "GOSUB sub0", "LOOP"]
    subroutines = ["", "#sub0"]
    for i in range(1, max(2, lines // 400)):
        subroutines += _setup(rng, i)
    subroutines.append("RETURN")
    blocks = -(-lines // (_SUBROUTINES * 10))  # a subroutine holds about 11 lines per block asked for
    index = 0
    while len(main) + len(subroutines) < lines - 8:
        index += 1
        main.append(f"  GOSUB sub{index} : REM step {index}")
        subroutines += ["", f"#sub{index}"]
        for _ in range(rng.randint(blocks, 3 * blocks)):
            subroutines += rng.choice(_BLOCKS)(rng, index)
        subroutines.append(f"RETURN : REM end of sub{index}")
    main += ["ENDL", "END"]
    handler = ["", "#ONERROR", "  PRINT ERR", "  RETURN"]
    return "\n".join(main + subroutines + handler) + "\n"


def _program_of(size: str) -> str:
    """The program for ``size``: a line count (``10000``) or megabytes (``1.4MB``)."""
    if not size.upper().endswith("MB"):
        return v3_program(int(size))
    sample = v3_program(1000)
    return v3_program(round(1000 * float(size[:-2]) * 1e6 / len(sample.encode())))


def _measure(size: str, repeat: int, memory: bool) -> dict[str, object]:
    """In this (fresh) process: paired rounds of migration and parse, or the peaks of one of each."""
    text = _program_of(size)
    migrate(v3_program(200))  # grammars, keyword database, manuals' sections: loaded once, untimed
    figures: dict[str, object] = {"lines": text.count("\n"), "bytes": len(text.encode())}
    if memory:
        figures["peak"] = _peak(lambda: migrate(text))
        figures["parse_peak"] = _peak(lambda: mintlang.parse(text, dialect="v3"))
        return figures
    rounds: dict[str, list[float]] = {"parse": [], "migrate": [], "parse_cpu": [], "migrate_cpu": []}
    for _ in range(repeat):
        for name, action in (("parse", lambda: mintlang.parse(text, dialect="v3")), ("migrate", lambda: migrate(text))):
            mintlang.clear_caches()
            start, cpu = time.perf_counter(), time.process_time()
            action()
            rounds[name].append(time.perf_counter() - start)
            rounds[f"{name}_cpu"].append(time.process_time() - cpu)
    figures.update(rounds)
    return figures


def _peak(action: Callable[[], object]) -> int:
    """The most memory ``action`` held at once beyond what was allocated before it, caches cold."""
    mintlang.clear_caches()
    tracemalloc.start()
    before = tracemalloc.get_traced_memory()[0]
    action()
    peak = tracemalloc.get_traced_memory()[1] - before
    tracemalloc.stop()
    return peak


def _fresh(size: str, repeat: int, memory: bool) -> dict[str, object]:
    command = [sys.executable, __file__, "--measure", size, "--repeat", str(repeat), *(["--memory"] if memory else [])]
    return json.loads(subprocess.run(command, capture_output=True, text=True, check=True).stdout)


def _spread(values: list[float], scale: float = 1.0, digits: int = 2) -> str:
    low, mid, high = (v * scale for v in (min(values), statistics.median(values), max(values)))
    return f"{mid:.{digits}f} ({low:.{digits}f}-{high:.{digits}f})"


def _ratios(migration: list[float], parse: list[float]) -> list[float]:
    """Each round's migration over its parse."""
    return [m / p for m, p in zip(migration, parse, strict=True)]


def main() -> None:
    options = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    options.add_argument("sizes", nargs="*", default=["1000", "10000", "100000", "1.4MB"], help="lines, or MB")
    options.add_argument("--repeat", type=int, default=7)
    options.add_argument("--measure", help=argparse.SUPPRESS)
    options.add_argument("--memory", action="store_true", help=argparse.SUPPRESS)
    arguments = options.parse_args()
    if arguments.measure:
        print(json.dumps(_measure(arguments.measure, arguments.repeat, arguments.memory)))
        return
    rounds = f"median (min-max) of {arguments.repeat} paired rounds"
    print(f"mint-migrate beside mintlang.parse(text, dialect='v3') of the same text, {rounds}")
    print("targets: migration within 3x the parse, peak memory within 50x the input")
    for size in arguments.sizes:
        timed = _fresh(size, arguments.repeat, memory=False)
        traced = _fresh(size, 1, memory=True)
        parse, migration = timed["parse"], timed["migrate"]
        print(
            f"{timed['lines']:>7} lines {timed['bytes'] / 1e6:5.2f} MB:"
            f"  parse {_spread(parse, 1000, 0)} ms"
            f"  migrate {_spread(migration, 1000, 0)} ms"
            f"  = {_spread(_ratios(migration, parse), digits=1)}x the parse"
            f" ({_spread(_ratios(timed['migrate_cpu'], timed['parse_cpu']), digits=1)}x in CPU time);"
            f"  peak {traced['peak'] / 1e6:.0f} MB = {traced['peak'] / timed['bytes']:.0f}x the input"
            f" (parse {traced['parse_peak'] / timed['bytes']:.0f}x)"
        )


if __name__ == "__main__":
    main()
