"""Running one test: the program (its configuration first) under its scenario, judged as ``mint-run --expect``."""

from __future__ import annotations

import time
from collections.abc import Mapping
from enum import StrEnum
from pathlib import Path

from mintlang.cli.settings import whole_settings
from mintlang.detection import dialect_hint
from mintlang.dialect import Dialect
from mintlang.records import record
from mintlang.runtime.hardware import machine
from mintlang.runtime.run import run_source
from mintlang.runtime.scenario import (
    Outcome,
    Scenario,
    ScenarioError,
    ScenarioFileError,
    expectations_pass,
    load_scenario,
    stop_fails,
)
from mintlang.runtime.scenario.stimulus import DrivesEnabled, merge
from mintlang.runtime.simulation import Limits, Stop, StopReason
from mintlang.runtime.testing.coverage import FileCoverage, Recorder
from mintlang.runtime.testing.discovery import TestCase, configuration_of
from mintlang.settings import FileSettings, Overrides, SettingsError
from mintlang.source import SourceFile, read_source


class Verdict(StrEnum):
    PASSED = "passed"
    FAILED = "failed"  # an expectation did not hold, or the run stopped as none asked
    ERROR = "error"  # the test could not be judged: a file unreadable, no expectation, the program refused


@record
class Check:
    """One expectation as the report shows it."""

    what: str
    when: str
    expected: str
    actual: str
    held: bool
    origin: str
    detail: str


@record
class TestResult:
    case: TestCase
    verdict: Verdict
    stopped: str  # why the run ended (end, error, deadlock …), or "" when it never ran
    message: str  # the stop's message, or why the test is an error
    checks: tuple[Check, ...]
    simulated_ms: int
    seconds: float
    coverage: tuple[FileCoverage, ...] = ()  # with ``Options.coverage``
    stop_failed: bool = False  # the run stopped on an error, a deadlock … that no ``stopped`` expectation asked for
    hint: str | None = None  # the program looks like MintMT, run as v4 by default (``dialect_hint``)
    ignored_directives: tuple[str, ...] = ()  # REM @sim and @expect lines of the configuration file, not applied
    place: str | None = None  # ``file:line`` of the statement a run that did not end by itself stopped at, or of the
    # first directive or scenario line that could not be read
    problems: tuple[ScenarioError, ...] = ()  # the directive and scenario mistakes ``message`` lists, each at its place


@record
class Options:
    """What every test of a run shares; a controller or dialect not given comes from each program's settings
    file (``[tool.mint]``), as ``mint check`` and ``mint-run`` take it."""

    controller: str | None = None
    dialect: Dialect | None = None
    until_ms: int | None = None
    max_wall_s: float | None = 60.0
    drives_enabled: bool = False
    coverage: bool = False
    overrides: Overrides = Overrides()  # the command line's layer above the settings file (--no-config)


@record
class _Read:
    """What a test runs from, read before its scenario: an expectation v4 refuses (a MintMT reading such as
    ``SUSPEND(0)``) is one reason a program needs its hint, so the hint goes with whatever stops the test after."""

    settings: FileSettings
    dialect: Dialect
    program: SourceFile
    hint: str | None  # the program looks like MintMT, run as v4 by default (``dialect_hint``)


def run_case(case: TestCase, options: Options) -> TestResult:
    """Run ``case``; every problem becomes its result, never an exception (it runs in a worker process)."""
    began = time.perf_counter()
    try:
        read = _read(case, options)
    except (OSError, SettingsError, ValueError) as error:
        return _error(case, str(error), began)
    if (binary := read.program.binary()) is not None:
        return _error(case, binary, began)
    try:
        return _run(case, options, began, read)
    except ScenarioFileError as error:  # a directive or scenario line: the Testing view points at its place
        place = next((each.place for each in error.errors if each.place), None)
        return _error(case, str(error), began, place=place, problems=error.errors, hint=read.hint)
    except (OSError, SettingsError, ValueError) as error:
        return _error(case, str(error), began, hint=read.hint)


def _read(case: TestCase, options: Options) -> _Read:
    """The settings, dialect and program of ``case``; a binary program has no text to hint about."""
    settings = whole_settings(case.program, options.overrides)
    dialect = options.dialect or settings.dialect.value
    program = read_source(case.program)
    chosen = options.dialect is not None or settings.dialect.chosen
    hint = None if chosen or program.binary() is not None else dialect_hint(str(case.program), program.text, dialect)
    return _Read(settings, dialect, program, hint)


def _run(case: TestCase, options: Options, began: float, read: _Read) -> TestResult:
    settings, dialect, program, hint = read.settings, read.dialect, read.program, read.hint
    controller = options.controller or _configured_controller(settings, dialect)
    simulated = machine(controller, dialect)
    scenario = load_scenario(case.scenario, simulated, dialect) if case.scenario else Scenario()
    if options.drives_enabled:
        scenario = merge(scenario, Scenario(drives=(DrivesEnabled(),)))
    partner = configuration_of(case.program, settings)
    configuration = read_source(partner).text if partner is not None else None
    files: dict[str, Path] = {"program": case.program}
    if partner is not None:
        files["configuration"] = partner
    recorder = Recorder(files, dialect) if options.coverage else None
    result = run_source(
        program.text,
        config=configuration,
        controller=controller,
        dialect=dialect,
        scenario=scenario,
        limits=Limits(until_ms=options.until_ms, max_wall_s=options.max_wall_s, end_when_checked=True),
        on_start=recorder.attach if recorder is not None else None,
        name=str(case.program),
        config_name=str(partner),
    )
    coverage = recorder.result() if recorder is not None else ()
    checks = tuple(_check(outcome) for outcome in result.outcomes)
    stopped = result.stop.reason.value
    ignored = result.ignored_directives
    place = _place(result.stop, files)
    if result.refused:
        return _error(case, result.stop.message, began, stopped=stopped, hint=hint, ignored=ignored, place=place)
    if not checks:
        missing = "no expectation to check: add REM @expect lines or [[expect]] to its scenario"
        return _error(case, missing, began, hint=hint, ignored=ignored)
    verdict = Verdict.PASSED if expectations_pass(result.outcomes, stopped) else Verdict.FAILED
    elapsed = time.perf_counter() - began
    stop_failed = stop_fails(result.outcomes, stopped)
    return TestResult(
        case,
        verdict,
        stopped,
        result.stop.message,
        checks,
        result.stop.time_ms,
        elapsed,
        coverage,
        stop_failed,
        hint,
        ignored,
        place,
    )


def _place(stop: Stop, files: Mapping[str, Path]) -> str | None:
    """``file:line`` of the statement an error, a deadlock or a limit stopped the run at (the controller's message
    says only ``PROGRAM`` or ``CONFIGURATION`` and the line), as each expectation names its own; none for a run
    that ended by itself."""
    if stop.reason in (StopReason.END, StopReason.UNTIL) or stop.line is None or stop.unit not in files:
        return None
    return f"{files[stop.unit]}:{stop.line}"


def _configured_controller(settings: FileSettings, dialect: Dialect) -> str | None:
    """The settings file's controller; none (the dialect's own default) when it names none or the program is v3."""
    given = settings.controller
    return given.value.value if given.chosen and dialect is not Dialect.V3 else None


def _check(outcome: Outcome) -> Check:
    expectation = outcome.expectation
    when = "end" if expectation.at_ms is None else f"{expectation.at_ms} ms"
    what, expected, origin = expectation.what, expectation.expected, str(expectation.origin)
    return Check(what, when, expected, outcome.actual, outcome.held, origin, outcome.detail)


def _error(
    case: TestCase,
    message: str,
    began: float,
    *,
    stopped: str = "",
    hint: str | None = None,
    ignored: tuple[str, ...] = (),
    place: str | None = None,
    problems: tuple[ScenarioError, ...] = (),
) -> TestResult:
    elapsed = time.perf_counter() - began
    return TestResult(
        case,
        Verdict.ERROR,
        stopped,
        message,
        (),
        0,
        elapsed,
        hint=hint,
        ignored_directives=ignored,
        place=place,
        problems=problems,
    )
