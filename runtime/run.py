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
from mintlang.keyworddb.model import Controller as ControllerName
from mintlang.runtime.controller import Controller, build_controller
from mintlang.runtime.errors import MintError, NotSimulated, error_title
from mintlang.runtime.hardware import simulated
from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.observation import AxisState, Observation, Refused, axis_state
from mintlang.runtime.scenario import ScenarioFileError, merge, parse_directives
from mintlang.runtime.scenario.expectations import Expectation, Outcome, TerminalExpectation, evaluate, not_reached
from mintlang.runtime.scenario.stimulus import Scenario
from mintlang.runtime.simulation import Limits, Simulator, Stop
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.units import Unit


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


@dataclass(frozen=True, slots=True)
class _CompileError:
    """The first error the controller's compiler finds, which stops the run before the file it is in starts."""

    code: int
    unit: Unit
    line: int
    statement: str
    message: str  # with the checker's explanation, for the report
    printed: str  # as the controller prints it: ``C2014: PROGRAM Incorrect loop terminator [line 12]``


def _compile_error(analysis: mintlang.Analysis) -> _CompileError | None:
    """The configuration is compiled (and run) first, then the program (000:269-271)."""
    model = analysis.model
    for unit, diagnostics, document in (
        (Unit.CONFIGURATION, analysis.configuration, model.configuration),
        (Unit.PROGRAM, analysis.program, model.program),
    ):
        for diagnostic in diagnostics:
            if diagnostic.mint_error is not None and not diagnostic.at_run_time and document is not None:
                line = document.line_index.position(diagnostic.span.start).line
                text = document.source[diagnostic.span.start : diagnostic.span.end]
                code, name = diagnostic.mint_error, unit.value.upper()
                message = f"C{code:04d}: {name} {diagnostic.message} [line {line}]"
                printed = f"C{code:04d}: {name} {error_title(code)} [line {line}]"
                return _CompileError(code, unit, line, text, message, printed)
    return None


def _not_run(message: str, scenario: Scenario, code: int | None = None) -> RunResult:
    """A run the simulator cannot start (a keyword it does not model, an array it cannot size); ERR tells why."""
    stop = Stop(StopReason.ERROR, 0, None, None, None, message)
    refused = Refused(float(code) if code is not None else -1.0, 0.0)
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
    naming the program ``name`` (its path, on the command line). A file the
    controller's compiler rejects does not run: when it is the program, the
    configuration still runs first, as on the controller.
    """
    directives, problems = parse_directives(source, name, controller=simulated(controller))
    if problems:
        raise ScenarioFileError(problems)
    scenario = merge(directives, scenario) if scenario is not None else directives
    analysis = mintlang.check_application(source, controller=controller, config=config)
    refused = _compile_error(analysis)
    model = analysis.model
    if refused is not None:  # what runs before the compiler stops: the configuration, if the program is at fault
        runs_first = config if refused.unit is Unit.PROGRAM else None
        model = mintlang.check_application("", controller=controller, config=runs_first).model
    return _simulate(model, scenario, limits or Limits(), refused, echo=echo, on_tick=on_tick)


def _simulate(
    model: SemanticModel,
    scenario: Scenario,
    limits: Limits,
    refused: _CompileError | None,
    *,
    echo: Callable[[str], None] | None,
    on_tick: Callable[[Controller, int], None] | None,
) -> RunResult:
    try:
        built = build_controller(
            model, scenario, slice_statements=limits.slice_statements, host_port=limits.host_port, echo=echo
        )
    except NotSimulated as missing:
        return _not_run(str(missing), scenario)
    except MintError as error:
        return _not_run(error.describe(), scenario, error.code)
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
    if refused is not None and stop.reason is StopReason.END:
        unit = refused.unit.value
        stop = Stop(StopReason.ERROR, stop.time_ms, unit, refused.line, refused.statement, refused.message)
        built.vm.record_error(refused.code, refused.line, None)
        built.terminal.announce(refused.printed)
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
