"""Running an application from source: check, compile, simulate, collect the result.

The controller compiles a program before running it, so a compile-time error
(3001 undeclared variable, a mismatched block …) stops the run before its
first statement, with the error where the checker reports it. The other errors
``mint check`` finds without running (an index outside its array, a constant
axis the controller lacks) are the controller's run-time errors: the line
raises them when it runs, so ``#ONERROR`` sees them.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from functools import partial

import mintlang
from mintlang.controllers import profile
from mintlang.keyworddb.model import Controller as ControllerName
from mintlang.runtime.controller import Controller, build_controller
from mintlang.runtime.errors import MintError, NotSimulated
from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.observation import AxisState, Observation, Refused, axis_state
from mintlang.runtime.scenario import ScenarioFileError, merge, parse_directives
from mintlang.runtime.scenario.expectations import Expectation, Outcome, TerminalExpectation, evaluate, not_reached
from mintlang.runtime.scenario.stimulus import Scenario
from mintlang.runtime.simulation import Limits, Simulator, Stop


@dataclass(frozen=True, slots=True)
class RunResult:
    stop: Stop
    err: float
    erl: float
    outputs: int
    relay: int
    axes: tuple[AxisState, ...]
    terminal: str  # the output, or its last TRANSCRIPT_LIMIT characters (mint-run streams all of it)
    host_replies: tuple[tuple[int, bytes], ...]
    outcomes: tuple[Outcome, ...]
    inert_settings: tuple[str, ...] = ()  # settings the program wrote that the simulation does not model
    terminal_dropped: int = 0  # characters printed before those ``terminal`` keeps


def _not_run(
    message: str,
    scenario: Scenario,
    *,
    code: int | None = None,
    line: int | None = None,
    unit: str | None = None,
    statement: str | None = None,
) -> RunResult:
    """A run refused before its first statement; ERR and ERL tell the controller's compile error, if it is one.

    The expectations are still judged: a case may expect a program to fail to compile.
    """
    stop = Stop(StopReason.ERROR, 0, unit, line, statement, message)
    refused = Refused(float(code) if code is not None else -1.0, float(line or 0))
    outcomes = tuple(
        evaluate(expectation, refused) if expectation.at_ms is None else not_reached(expectation, 0)
        for expectation in scenario.expectations
    )
    return RunResult(stop, refused.err, refused.erl, 0, 0, (), "", (), outcomes)


def run_source(
    source: str,
    *,
    config: str | None = None,
    controller: ControllerName | str = ControllerName.NEXTMOVE_PCI,
    scenario: Scenario | None = None,
    limits: Limits | None = None,
    echo: Callable[[str], None] | None = None,
    on_tick: Callable[[Controller, int], None] | None = None,
    name: str = "program",
) -> RunResult:
    """Run a program (and its configuration file) to the end or a limit; never raises for the program's faults.

    The program's own ``REM @sim`` directives are merged under ``scenario``; a
    directive that cannot be read raises ``ScenarioFileError`` before anything runs,
    naming the program ``name`` (its path, on the command line).
    """
    directives, problems = parse_directives(source, name, controller=profile(controller))
    if problems:
        raise ScenarioFileError(problems)
    scenario = merge(directives, scenario) if scenario is not None else directives
    limits = limits or Limits()
    analysis = mintlang.check_application(source, controller=controller, config=config)
    for unit, diagnostics, document in (
        ("configuration", analysis.configuration, analysis.model.configuration),
        ("program", analysis.program, analysis.model.program),
    ):
        for diagnostic in diagnostics:
            if diagnostic.mint_error is not None and not diagnostic.at_run_time and document is not None:
                line = document.line_index.position(diagnostic.span.start).line
                text = document.source[diagnostic.span.start : diagnostic.span.end]
                message = f"C{diagnostic.mint_error or 0:04d}: {unit.upper()} {diagnostic.message} [line {line}]"
                return _not_run(message, scenario, code=diagnostic.mint_error, line=line, unit=unit, statement=text)
    try:
        built = build_controller(
            analysis.model, scenario, slice_statements=limits.slice_statements, host_port=limits.host_port, echo=echo
        )
    except NotSimulated as missing:
        return _not_run(str(missing), scenario)
    except MintError as error:
        return _not_run(error.describe(), scenario, code=error.code)
    simulator = Simulator(built, limits)
    outcomes: list[Outcome] = []
    end_expectations = []
    unchecked: dict[int, Expectation] = {}  # timed expectations whose time has not come yet

    def check(number: int) -> None:
        outcomes.append(evaluate(unchecked.pop(number), Observation(built)))

    for number, expectation in enumerate(scenario.expectations):
        if expectation.at_ms is None:
            end_expectations.append(expectation)
        else:
            unchecked[number] = expectation
            simulator.at(expectation.at_ms, partial(check, number))
    for expectation in scenario.expectations:
        if isinstance(expectation, TerminalExpectation):
            built.terminal.watch(expectation.text)  # found in all the output, not only in what is kept
    if on_tick is not None:
        simulator.on_tick = lambda tick: on_tick(built, tick)
    stop = simulator.run()
    # a check the run never reached did not hold: dropping it would let a run that stops early pass
    outcomes.extend(not_reached(expectation, stop.time_ms) for expectation in unchecked.values())
    final = Observation(built, stop.reason.value)
    outcomes.extend(evaluate(expectation, final) for expectation in end_expectations)
    return RunResult(
        stop,
        built.vm.err,
        built.vm.erl,
        built.io.out,
        built.io.relay,
        tuple(axis_state(axis) for axis in built.axes),
        built.terminal.text,
        tuple(built.world.host_replies),
        tuple(outcomes),
        tuple(sorted(built.inert.used)),
        built.terminal.dropped,
    )
