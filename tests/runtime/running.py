"""Running a program for a test, twice: skipping idle ticks and stepping every tick.

The simulator jumps over ticks where nothing can change; every scenario is
therefore also run tick by tick, and both runs must agree on everything a
user can observe. A test that uses ``simulate`` checks that for free.
"""

from __future__ import annotations

from dataclasses import replace

from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import RunResult, run_source
from mintlang.runtime.scenario.stimulus import Scenario
from mintlang.runtime.simulation import Limits


def simulate(
    source: str,
    *,
    config: str | None = None,
    controller: str = "nextmove-bx",
    scenario: Scenario | None = None,
    until_ms: int | None = 60_000,
    enable: bool = True,
) -> RunResult:
    """Run ``source`` (after a configuration that enables every drive, unless ``enable`` is False)."""
    if enable and config is None:
        config = "RESETALL\n"
    limits = Limits(until_ms=until_ms, max_wall_s=60.0)
    skipping = run_source(source, config=config, controller=controller, scenario=scenario, limits=limits)
    stepping = run_source(
        source, config=config, controller=controller, scenario=scenario, limits=replace(limits, every_tick=True)
    )
    assert observable(skipping) == observable(stepping), "skipping idle ticks changed the result"
    return skipping


def observable(result: RunResult) -> tuple[object, ...]:
    return (result.stop, result.err, result.erl, result.outputs, result.relay, result.axes, result.terminal)


def assert_syntax_error_before_it_runs(line: str) -> None:
    """``line``, third in a program whose second prints "before", is a syntax error: the controller finds it
    when it compiles the program, before running any of it (000:4563-4568), and prints it as a compile-time
    error naming line 3 (000:4584-4588)."""
    result = simulate(f'DIM a\nPRINT "before"\n{line}\n')
    assert result.stop.reason is StopReason.ERROR
    assert result.err == 2003
    assert "before" not in result.terminal
    assert result.terminal.startswith("C2003: PROGRAM Syntax error")
    assert result.terminal.endswith("[line 3]\n")
