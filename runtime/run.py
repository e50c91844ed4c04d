"""Running an application from source: check, compile, simulate, collect the result.

The controller compiles a program before running it, so a compile-time error
(3001 undeclared variable, a mismatched block …) stops the run before its
first statement, with the error where the checker reports it. The other errors
``mint check`` finds without running (an index outside its array, a constant
axis the controller lacks) are the controller's run-time errors: the line
raises them when it runs, so ``#ONERROR`` sees them.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping
from dataclasses import replace
from functools import partial

import mintlang
from mintlang.controllers import ControllerProfile
from mintlang.diagnostics import Diagnostic, Span
from mintlang.dialect import Dialect
from mintlang.keyworddb.model import Controller as ControllerName
from mintlang.records import record
from mintlang.runtime.configuration_only import configuration_only
from mintlang.runtime.controller import Controller, build_controller
from mintlang.runtime.dialects import semantics
from mintlang.runtime.errors import ErrorStyle, MintError, NotSimulated
from mintlang.runtime.hardware import machine
from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.observation import AxisState, Observation, Refused, axis_state
from mintlang.runtime.scenario import ScenarioFileError, ignored_directives, merge, parse_directives
from mintlang.runtime.scenario.expectations import (
    Expectation,
    Outcome,
    StoppedExpectation,
    TerminalExpectation,
    evaluate,
    not_reached,
)
from mintlang.runtime.scenario.stimulus import Scenario
from mintlang.runtime.simulation import Limits, Simulator, Stop
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.units import Unit


@record
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
    refused: bool = False  # the controller's compiler rejected a file: the program never ran (``stop`` says why)
    read_leniently: tuple[str, ...] = ()  # what the controller would refuse, run as mint check's safe fix writes it
    ignored_directives: tuple[str, ...] = ()  # REM @sim and @expect lines of the configuration file, not applied
    not_run: tuple[str, ...] = ()  # what the configuration file holds and the run never runs (configuration_only)


@record
class _CompileError:
    """The first error the controller's compiler finds, which stops the run before the file it is in starts."""

    code: int | str  # the error's number, or the code of a check the dialect's compiler stops on (W111 in v3)
    unit: Unit
    line: int
    statement: str
    message: str  # with the checker's explanation, for the report
    printed: str  # as the controller prints it: ``C2014: PROGRAM Incorrect loop terminator [line 12]``


@record
class _Hooks:
    """The caller's observers of a run (``run_source``)."""

    echo: Callable[[str], None] | None
    on_tick: Callable[[Controller, int], None] | None
    on_start: Callable[[Controller], None] | None
    on_simulator: Callable[[Simulator], None] | None
    functions: Mapping[str, Callable[..., float]] | None = None  # in place of the dialect's (build_controller)


_ORDER = {Unit.CONFIGURATION: 0, Unit.PROGRAM: 1}  # compile order of the files
_LINE_END = re.compile(r"[\r\n]|$")


def compile_refusal(
    source: str,
    *,
    config: str | None = None,
    controller: ControllerName | str | None = None,
    dialect: Dialect | str = Dialect.V4,
) -> str | None:
    """The message with which the controller's compiler refuses the program or its configuration (as
    ``run_source`` stops on it), or None: a debugger binds no breakpoint in a program that never starts."""
    refused = _compiled(source, config, dialect, machine(controller, dialect))[1]
    return refused.message if refused is not None else None


def _compiled(
    source: str, config: str | None, dialect: Dialect | str, simulated: ControllerProfile
) -> tuple[mintlang.Analysis, _CompileError | None]:
    """The application as checked on the machine simulated, and the first error its compiler stops on."""
    analysis = mintlang.check_application(  # the controller reads no suppression comment
        source, dialect=dialect, controller=simulated.controller, config=config, suppressions=False
    )
    return analysis, _compile_error(analysis, semantics(dialect).errors(lambda axis: 0))


def _compile_error(analysis: mintlang.Analysis, errors: ErrorStyle) -> _CompileError | None:
    """The first error the compiler finds: the configuration is compiled (and run) first, then the program
    (000:269-271)."""
    model = analysis.model
    found: list[tuple[int, int, int | str, Unit, Span, str]] = []  # (file order, offset, code, unit, span, explanation)
    for unit, _ in model.documents():
        diagnostics = analysis.configuration if unit is Unit.CONFIGURATION else analysis.program
        first = next((d for d in diagnostics if _stops_compiling(d, errors)), None)
        if first is not None:
            code = first.mint_error if first.mint_error is not None else first.code
            found.append((_ORDER[unit], first.span.start, code, unit, first.span, first.message))
    if not found:
        return None
    _, _, code, unit, span, explanation = min(found, key=lambda problem: problem[:2])
    document = model.document(unit)
    line = document.line_index.position(span.start).line
    start = document.line_index.line_start(line)
    # the whole line, as a run-time error quotes its statement: the span alone may be empty (a missing TO)
    text = document.source[start : _LINE_END.search(document.source, start).start()].strip()
    message = errors.compiled(code, unit.value, line, explanation)
    return _CompileError(code, unit, line, text, message, errors.compiled(code, unit.value, line))


def _stops_compiling(diagnostic: Diagnostic, errors: ErrorStyle) -> bool:
    """Whether the compiler stops on what ``diagnostic`` reports: an error it raises before the program runs, or a
    check of the toolchain's that the dialect's compiler makes too (a v3 line past 127 characters)."""
    if diagnostic.mint_error is not None:
        return not diagnostic.at_run_time
    return diagnostic.code in errors.stops_compiling


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
    controller: ControllerName | str | None = None,
    dialect: Dialect | str = Dialect.V4,
    scenario: Scenario | None = None,
    limits: Limits | None = None,
    echo: Callable[[str], None] | None = None,
    on_tick: Callable[[Controller, int], None] | None = None,
    on_start: Callable[[Controller], None] | None = None,
    on_simulator: Callable[[Simulator], None] | None = None,
    name: str = "program",
    config_name: str = "configuration",
    functions: Mapping[str, Callable[..., float]] | None = None,
) -> RunResult:
    """Run a program (and its configuration file) to the end or a limit; never raises for the program's faults.

    The program is in ``dialect`` (Mint v4, or v3 on one of the v3 guide's
    controllers: a controller of the other generation is a ``ValueError``). The
    program's own ``REM @sim`` directives are merged under ``scenario``; a
    directive that cannot be read raises ``ScenarioFileError`` before anything runs,
    naming the program ``name`` (its path, on the command line); one in the
    configuration ``config_name`` is not applied but noted (``ignored_directives``). A file the
    controller's compiler rejects does not run: when it is the program, the
    configuration still runs first, as on the controller.

    ``on_tick`` is called after each processed tick (every tick with
    ``Limits.every_tick``), ``on_start`` once with the controller before the
    first: an ``echo`` that wants the time or the statement printing
    (``controller.clock.now``, ``controller.vm.current_site()``) gets it there.
    ``on_simulator`` is given the simulator after that, to hook into its ticks
    (a debugger's checkpoints, ``Simulator.before_tick``). ``functions`` replace
    the dialect's numeric functions of those names (``build_controller``).
    """
    simulated = machine(controller, dialect)
    directives, problems = parse_directives(source, name, controller=simulated, dialect=dialect)
    if problems:
        raise ScenarioFileError(problems)
    scenario = merge(directives, scenario) if scenario is not None else directives
    base = simulated.controller  # the v4 machine a v3 controller is simulated on
    analysis, refused = _compiled(source, config, dialect, simulated)
    model = analysis.model
    if refused is not None:  # what runs before the compiler stops: the configuration, if the program is at fault
        runs_first = config if refused.unit is Unit.PROGRAM else None
        model = mintlang.check_application("", dialect=dialect, controller=base, config=runs_first).model
    hooks = _Hooks(echo, on_tick, on_start, on_simulator, functions)
    result = _simulate(model, simulated, scenario, limits or Limits(), refused, hooks=hooks)
    lenient = _read_leniently(analysis)
    ignored = ignored_directives(config, config_name, dialect) if config is not None else ()
    not_run = configuration_only(analysis.model, config_name)
    if lenient or ignored or not_run:
        return replace(result, read_leniently=lenient, ignored_directives=ignored, not_run=not_run)
    return result


def _ending_at_the_last_check(limits: Limits, expectations: tuple[Expectation, ...]) -> Limits:
    """``limits``, ending at the last expectation's time when ``Limits.end_when_checked`` asks for it and every
    expectation is timed (one at the end, a ``stopped`` one included, needs the run to end by itself)."""
    last = _last_check(expectations)
    if not limits.end_when_checked or limits.until_ms is not None or last is None:
        return limits
    return replace(limits, until_ms=last, until_message=f"every expectation was checked (the last at {last} ms)")


def _last_check(expectations: tuple[Expectation, ...]) -> int | None:
    """The time of the last of ``expectations`` when there are some and every one is timed, else None."""
    times = [expectation.at_ms for expectation in expectations]
    if not times or None in times:
        return None
    return max(at for at in times if at is not None)


def _waiting_for_the_end(stop: Stop, expectations: tuple[Expectation, ...], at_end: list[Expectation]) -> Stop:
    """``stop`` at the wall-clock limit, saying which expectation kept the run going when one checked at the end
    (other than how it stops) waited for a program that never ended, as a machine's main loop does not; or, in a
    plain run whose checks were all timed, that they were done long before and what ends such a run there."""
    waiting = next((each for each in at_end if not isinstance(each, StoppedExpectation)), None)
    if waiting is not None:
        hint = f"the program has not ended, and the expectation at {waiting.origin} is checked at its end"
        return replace(stop, message=f"{stop.message}; {hint}: give it a time, or set --until-ms")
    last = _last_check(expectations)  # None when one is checked at the end
    if last is None or stop.time_ms < last:
        return stop
    hint = (
        f"every expectation was checked by {last} ms, and a plain run goes on until the program ends: "
        f"set --until-ms {last}, or run it as a test (mint test), which ends at the last check"
    )
    return replace(stop, message=f"{stop.message}; {hint}")


def _read_leniently(analysis: mintlang.Analysis) -> tuple[str, ...]:
    """What the controller would refuse and the simulator runs all the same, one note a line, in compile order.

    The controller knows only plain quotes, but text copied from the guide (or a word processor) carries
    curly ones where plain ones were meant (W101): the simulator runs the program as ``mint check --fix``
    would write it. A line longer than the controller takes (W111) keeps the program from downloading
    (000:18454-18456); the simulator runs it as written. Either way it says so, so that neither tool passes
    such a program in silence (BEHAVIOUR.md). A Mint v3 compiler stops on that line (001:12999-13001), and so
    does the run: what the dialect's compiler stops on is no note."""
    stops_compiling = semantics(analysis.model.program.dialect).errors(lambda axis: 0).stops_compiling
    notes: list[str] = []
    for unit, document in analysis.model.documents():
        diagnostics = analysis.configuration if unit is Unit.CONFIGURATION else analysis.program
        found = {(document.line_index.position(d.span.start).line, d.code): d.message for d in diagnostics}
        for (line, code), message in sorted(found.items()):
            if code not in stops_compiling and (note := _lenient_note(code, message)) is not None:
                notes.append(f"{unit.value} line {line}: {note}")
    return tuple(notes)


def _lenient_note(code: str, message: str) -> str | None:
    """The note for a diagnostic of ``code`` the controller would refuse and the simulator runs past; else None."""
    if code == "W101":
        return (
            "typographic quotes read as plain ones; the controller accepts only plain quotes (mint check --fix"
            " writes them)"
        )
    if code == "W111":
        return f"{message}, and would not download the program (000:18454-18456); run here as written"
    return None


def _simulate(
    model: SemanticModel,
    simulated: ControllerProfile,
    scenario: Scenario,
    limits: Limits,
    refused: _CompileError | None,
    *,
    hooks: _Hooks,
) -> RunResult:
    try:
        built = build_controller(
            model,
            scenario,
            machine=simulated,
            slice_statements=limits.slice_statements,
            host_port=limits.host_port,
            echo=hooks.echo,
            functions=hooks.functions,
        )
    except NotSimulated as missing:
        return _not_run(str(missing), scenario)
    except MintError as error:
        return _not_run(error.describe(), scenario, error.code)
    simulator = Simulator(built, _ending_at_the_last_check(limits, scenario.expectations))
    built.vm.sleeps = not limits.every_tick  # stepping every tick tries every blocked statement, as a reference
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
    on_tick = hooks.on_tick
    if on_tick is not None:
        simulator.on_tick = lambda tick: on_tick(built, tick)
    if hooks.on_start is not None:
        hooks.on_start(built)
    if hooks.on_simulator is not None:
        hooks.on_simulator(simulator)
    stop = simulator.run()
    if refused is not None and stop.reason is StopReason.END:
        unit = refused.unit.value
        stop = Stop(StopReason.ERROR, stop.time_ms, unit, refused.line, refused.statement, refused.message)
        if model.program.dialect.modern:  # v3's ERR holds only what #ONERROR can see (001:4916)
            built.vm.record_error(refused.code, refused.line, None)
        built.vm.announce(refused.printed)
    if stop.reason is StopReason.WALL_LIMIT and limits.until_ms is None:
        stop = _waiting_for_the_end(stop, scenario.expectations, end_expectations)
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
        refused is not None,
    )
