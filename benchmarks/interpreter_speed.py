"""Statements per second of a tight arithmetic loop in ``mint-run``, beside CPython running the same loop.

Run: ``.venv/bin/python benchmarks/interpreter_speed.py [--n 200000] [--repeat 7]``
(``benchmarks/runtime_speed.py`` runs it too, after the simulated-time figure).

Two loops, each in Mint and in Python:

- FOR: ``FOR i = 1 TO n`` / ``s = s + i * 2 - 1`` / ``NEXT``. The controller runs
  2 statements per pass (the body's assignment and ``NEXT``, which steps ``i``
  and jumps back or leaves), plus ``DIM i``, ``DIM s``, ``FOR`` and ``PRINT s``
  once: **2n + 4 statements**. Python: ``for i in range(1, n + 1): s = s + i * 2 - 1``.
- WHILE: ``WHILE i < n`` / ``i = i + 1`` / ``s = s + i * 2 - 1`` / ``ENDW``. 3
  statements per pass (two assignments and ``ENDW``, which tests the condition
  again), plus the two DIMs, the first ``WHILE`` and ``PRINT s``: **3n + 4
  statements**. Python: ``while i < n: i = i + 1; s = s + i * 2 - 1`` on floats.

Both sides are credited with the same number of statements (the Mint count),
so the ratio of the rates is the ratio of the times. Before timing, one run of
each Mint program counts the operations the interpreter really executes
(every compiled operation wrapped in a counter, which also makes the loop
compiled whole step aside, ``runtime/interpreter/compiled_loops.py``) and
checks the count against the formula, that the ticks ran one full slice of 20
statements each (the last one the rest), that a run processing every tick
whole and the run as timed (the loop compiled whole) end at the same tick with
the same output, and that ``PRINT s`` printed what binary32 arithmetic gives;
the benchmark stops if any of that does not hold.

What is measured, and how:

- Mint: wall time of ``run_source`` on the program to its end, minus the wall
  time of the same call stopped after tick 0 (``--until-ms 0``) in the same
  round, which holds the fixed cost (check, compile, build the controller: a
  few ms) and the first slice of 20 statements; so the figure is the
  statements of ticks 1.. over their wall time. The loop never blocks and
  runs one slice of 20 statements a 1 ms tick (the controller's rate); its
  statements touch nothing but variables, so on the ticks between the ``FOR``
  (or first ``WHILE``) and ``PRINT`` nothing else can change and the simulator
  runs the slices alone, without sampling the world or ticking the axes and
  events (``runtime/interpreter/purity.py``), up to 255 ticks in one go; the
  loop's passes run as one generated Python loop over local variables
  (``runtime/interpreter/compiled_loops.py``). A diagnostic row runs the same
  program with one slice big enough for the whole loop (not the controller's
  timing).
- Python: the loop compiled into a function (locals, as CPython code normally
  runs) and called in the same round, with the garbage collector in the state
  the simulation runs in. ``mintlang`` pauses the collector while it parses and
  checks (``mintlang/allocation.py``) but not while it simulates; the counting
  run reads the state during the simulation and the reference gets the same.
  Collections during the timed loops are counted and printed for both.

Each round times Mint and Python back to back (paired rounds), so a noisy
machine slows both alike; the table gives the median and the spread (min-max)
of each rate and the median of the per-round ratios.
"""

from __future__ import annotations

import argparse
import gc
import statistics
import struct
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass

import mintlang.runtime.controller as controller_module
from mintlang.runtime.run import RunResult, run_source
from mintlang.runtime.simulation import Limits

CONTROLLER = "nextmove-bx"
SLICE = 20  # statements per 1 ms tick: Limits.slice_statements, the controller's rate
WHOLE = 10**9  # a slice that holds the whole loop, for the diagnostic row
_F32 = struct.Struct("<f")


def _f32(x: float) -> float:
    return _F32.unpack(_F32.pack(x))[0]


@dataclass(frozen=True)
class Loop:
    name: str
    mint: Callable[[int], str]  # n -> the Mint program
    python: str  # defines ``loop(n)``
    statements: Callable[[int], int]  # n -> statements the controller executes
    expected: Callable[[int], float]  # n -> the value PRINT s shows (binary32 arithmetic)


def _for_f32(n: int) -> float:
    s = 0.0
    for i in range(1, n + 1):
        s = _f32(_f32(s + _f32(i * 2.0)) - 1.0)
    return s


def _while_f32(n: int) -> float:
    i = s = 0.0
    while i < n:
        i = _f32(i + 1.0)
        s = _f32(_f32(s + _f32(i * 2.0)) - 1.0)
    return s


LOOPS = (
    Loop(
        "FOR",
        lambda n: f"DIM i\nDIM s\nFOR i = 1 TO {n}\n  s = s + i * 2 - 1\nNEXT\nPRINT s\n",
        "def loop(n):\n    s = 0.0\n    for i in range(1, n + 1):\n        s = s + i * 2 - 1\n    return s\n",
        lambda n: 2 * n + 4,
        _for_f32,
    ),
    Loop(
        "WHILE",
        lambda n: f"DIM i\nDIM s\nWHILE i < {n}\n  i = i + 1\n  s = s + i * 2 - 1\nENDW\nPRINT s\n",
        "def loop(n):\n    i = 0.0\n    s = 0.0\n    while i < n:\n        i = i + 1\n        s = s + i * 2 - 1\n"
        "    return s\n",
        lambda n: 3 * n + 4,
        _while_f32,
    ),
)


def _python_loop(loop: Loop) -> Callable[[int], float]:
    namespace: dict[str, object] = {}
    exec(compile(loop.python, f"<{loop.name} loop>", "exec"), namespace)
    return namespace["loop"]  # type: ignore[return-value]


def _run(source: str, limits: Limits, on_tick=None) -> RunResult:
    return run_source(source, controller=CONTROLLER, limits=limits, on_tick=on_tick)


@contextmanager
def _counted_operations(counter: list[int]) -> Iterator[None]:
    """Wrap every operation the linker compiles in a counter (for the counting run only, never timed)."""
    link = controller_module.link

    def counting_link(model, vm, *rest):
        linked = link(model, vm, *rest)

        def counted(operation):
            def run():
                counter[0] += 1
                return operation()

            return run

        vm.operations[:] = [counted(operation) for operation in vm.operations]
        return linked

    controller_module.link = counting_link
    try:
        yield
    finally:
        controller_module.link = link


def check(loop: Loop, n: int) -> tuple[bool, int]:
    """Count what the controller executes; stop unless it is what the module docstring says.

    Returns whether the collector is enabled during the simulation, and how many collections
    started after tick 0 (in the loop).
    """
    counter = [0]
    collector: list[bool] = []
    collections = _Collections()

    def on_tick(built, tick: int) -> None:
        collector.append(gc.isenabled())
        if tick == 0:
            collections.count = 0

    with _counted_operations(counter), collections:
        result = _run(loop.mint(n), Limits(slice_statements=SLICE), on_tick)
    executed, expected = counter[0], loop.statements(n)
    end = result.stop.time_ms
    problems = []
    if result.stop.reason.value != "end":
        problems.append(f"the run stopped with {result.stop}")
    if executed != expected:
        problems.append(f"{executed} statements executed, the formula says {expected}")
    for name, limits in (
        ("processing every tick whole", Limits(slice_statements=SLICE, every_tick=True)),
        ("the run as timed", Limits(slice_statements=SLICE)),
    ):
        other = _run(loop.mint(n), limits)
        if (other.stop.time_ms, other.terminal) != (end, result.terminal):
            problems.append(f"{name} ends at {other.stop.time_ms} ms with {other.terminal!r}, not {end}")
    if not SLICE * end < executed <= SLICE * (end + 1):
        problems.append(f"{executed} statements in {end + 1} ticks is not one full slice of {SLICE} a tick")
    printed = result.terminal.strip()
    wanted = loop.expected(n)
    if float(printed) != wanted:
        problems.append(f"PRINT s showed {printed}, binary32 arithmetic gives {wanted:.0f}")
    if len(set(collector)) != 1:
        problems.append("the collector changed state during the simulation")
    if problems:
        raise SystemExit(f"{loop.name} loop: " + "; ".join(problems))
    return collector[0], collections.count


class _Collections:
    """Counts the garbage collections that start while it is active."""

    def __init__(self) -> None:
        self.count = 0

    def __call__(self, phase: str, info: dict) -> None:
        if phase == "start":
            self.count += 1

    def __enter__(self) -> _Collections:
        gc.callbacks.append(self)
        return self

    def __exit__(self, *_: object) -> None:
        gc.callbacks.remove(self)


@contextmanager
def _collector(enabled: bool) -> Iterator[None]:
    was = gc.isenabled()
    gc.enable() if enabled else gc.disable()
    try:
        yield
    finally:
        gc.enable() if was else gc.disable()


def _timed(action: Callable[[], object]) -> float:
    start = time.perf_counter()
    action()
    return time.perf_counter() - start


@dataclass
class Rates:
    mint: list[float]
    whole: list[float]
    python: list[float]
    fixed_ms: list[float]
    mint_collections: int  # after tick 0 of the counting run
    python_collections: int  # in the timed rounds


def measure(loop: Loop, n: int, repeat: int) -> Rates:
    collector_on, collections_in_loop = check(loop, n)
    source = loop.mint(n)
    python = _python_loop(loop)
    statements = loop.statements(n)
    ticking, whole, until0 = Limits(slice_statements=SLICE), Limits(slice_statements=WHOLE), Limits(until_ms=0)
    _run(source, ticking)  # warm: the per-line caches and the keyword table, as in every later round
    rates = Rates([], [], [], [], collections_in_loop, 0)
    for _ in range(repeat):
        full = _timed(lambda: _run(source, ticking))
        fixed = _timed(lambda: _run(source, until0))  # the fixed cost and tick 0's slice
        rates.mint.append((statements - SLICE) / (full - fixed))
        rates.fixed_ms.append(fixed * 1000)
        one_slice = _timed(lambda: _run(source, whole))
        rates.whole.append(statements / (one_slice - fixed))  # tick 0 ran everything: not worth a correction
        with _collector(collector_on), _Collections() as collections:
            reference = _timed(lambda: python(n))
        rates.python_collections += collections.count
        rates.python.append(statements / reference)
    return rates


def _spread(values: list[float]) -> str:
    median, low, high = (value / 1e6 for value in (statistics.median(values), min(values), max(values)))
    return f"{median:7.3f} M/s ({low:.3f}-{high:.3f})".ljust(30)


def report(n: int, repeat: int) -> None:
    print(f"Tight arithmetic loop, n = {n}: statements per second, median (min-max) of {repeat} paired rounds")
    for loop in LOOPS:
        rates = measure(loop, n, repeat)
        ratios = [python / mint for python, mint in zip(rates.python, rates.mint, strict=True)]
        fixed = statistics.median(rates.fixed_ms)
        faster = f"{statistics.median(ratios):.1f}x ({min(ratios):.1f}-{max(ratios):.1f})"
        real_time = statistics.median(rates.mint) / SLICE / 1000  # simulated ms per wall ms
        print(f"  {loop.name} loop: {loop.statements(n)} statements; fixed cost of a run, subtracted: {fixed:.1f} ms")
        rows = (
            ("CPython (reference)", rates.python, ""),
            (f"mint-run, {SLICE} statements a 1 ms tick", rates.mint, f"CPython is {faster} faster"),
            ("mint-run, one slice (no per-tick work)", rates.whole, "diagnostic: not the controller's timing"),
        )
        for label, values, note in rows:
            print(f"    {label:<40} {_spread(values)} {note}".rstrip())
        print(f"    simulated time over wall time in this loop: {real_time:.0f}x real time")
        print(
            f"    garbage collections during the loop: mint-run {rates.mint_collections} (ticks 1.. of the counting"
            f" run), CPython {rates.python_collections} (all {repeat} rounds)"
        )


def main() -> None:
    options = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    options.add_argument("--n", type=int, default=200_000, help="passes of each loop (below 2**24: i is binary32)")
    options.add_argument("--repeat", type=int, default=7)
    arguments = options.parse_args()
    report(arguments.n, arguments.repeat)


if __name__ == "__main__":
    main()
