"""A ``launch`` request's arguments read into the application to run, as ``mint-run`` would run it.

The program's configuration file is the one ``mint-run`` pairs with it
(``config``, else the settings or ``<name>.cfg`` beside it; ``noConfig`` runs
none); scenario files add inputs, keys, host packets and plants; ``plot`` names
an image drawn of the run so far at each stop. The dialect
and controller not given are the project's settings file's (``mint.toml``), and
without one the dialect the program's text shows (``auto``) on the default
controller. Every mistake is a ``LaunchError`` whose message the editor shows
as it is.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping
from dataclasses import field, replace
from pathlib import Path
from typing import Any

from mintlang.controllers import ControllerProfile
from mintlang.detection import detect_dialect
from mintlang.dialect import Dialect
from mintlang.records import record
from mintlang.runtime.controller import Controller
from mintlang.runtime.debugger.evaluation import ExpressionReader
from mintlang.runtime.dialects import SIMULATED
from mintlang.runtime.hardware import machine
from mintlang.runtime.interpreter.vm import Site
from mintlang.runtime.outputs import OutputProblem, check_plot
from mintlang.runtime.run import RunResult, compile_refusal, run_source
from mintlang.runtime.scenario import ScenarioFileError, load_scenario, merge
from mintlang.runtime.scenario.stimulus import DrivesEnabled, Scenario
from mintlang.runtime.simulation import Limits, Simulator
from mintlang.runtime.trace import PlotUnavailable
from mintlang.semantic.units import Unit
from mintlang.settings import SettingsError, settings_for
from mintlang.settings.model import FileSettings, Given
from mintlang.source import read_source

_THEN = re.compile(r"\bTHEN\b", re.IGNORECASE)  # ends a one-line IF's condition: its statements follow
AUTO = "auto"  # the dialect the program's text shows (v4 or MintMT), as the editor's setting ``auto`` does


class LaunchError(Exception):
    """The launch cannot start: a file that cannot be read, an unknown controller, a bad scenario."""


@record
class Application:
    """Everything a run of the program needs, read once: every re-run (a step back) starts from it."""

    program: Path
    source: str
    configuration: Path | None
    configuration_source: str | None
    controller: str | None
    dialect: Dialect
    profile: ControllerProfile
    scenario: Scenario
    until_ms: int | None
    stop_on_entry: bool
    plot: Path | None = None  # the image the run so far is drawn to at each stop
    debugging: bool = True  # False for DAP's noDebug (VS Code's Run Without Debugging): the run stops nowhere

    def run(
        self,
        on_start: Callable[[Controller], None],
        echo: Callable[[str], None] | None = None,
        on_tick: Callable[[Controller, int], None] | None = None,
        on_simulator: Callable[[Simulator], None] | None = None,
    ) -> RunResult:
        """One run of the application, as long as the debugger lets it go (``untilMs`` at most)."""
        return run_source(
            self.source,
            config=self.configuration_source,
            controller=self.controller,
            dialect=self.dialect,
            scenario=self.scenario,
            # the user's pauses are not the program's time; each tick a statement runs in is processed whole,
            # so the machine shown where the program stops is up to date (ticks run alone would leave it behind)
            limits=Limits(until_ms=self.until_ms, max_wall_s=None, program_alone=False),
            echo=echo,
            on_tick=on_tick,
            on_start=on_start,
            on_simulator=on_simulator,
            name=str(self.program),
        )

    def refusal(self) -> str | None:
        """The compiler's message if it refuses the program or its configuration, as the run will stop on it."""
        return compile_refusal(
            self.source, config=self.configuration_source, controller=self.controller, dialect=self.dialect
        )

    def path_of(self, unit: str) -> Path | None:
        """The file of ``unit`` ("program" or "configuration"), as the interpreter's sites name them."""
        return self.program if unit == Unit.PROGRAM.value else self.configuration


def prepare(arguments: Mapping[str, Any]) -> Application:
    """The application the ``launch`` arguments describe; raises ``LaunchError``."""
    program = _path(arguments.get("program"), "program")
    if program is None:
        raise LaunchError("launch needs 'program': the path of the Mint program to debug")
    source = _read(program, "the program")
    try:
        settings = settings_for(program)
    except SettingsError as error:
        raise LaunchError(str(error)) from None
    configuration = _configuration(program, arguments, settings)
    configuration_source = _read(configuration, "the configuration file") if configuration is not None else None
    dialect = _dialect(arguments.get("dialect", _given(settings.dialect, AUTO)), source)
    controller = arguments.get("controller", _given(settings.controller, None))
    if controller is not None and not isinstance(controller, str):
        raise LaunchError("'controller' is the name of a controller, such as nextmove-pci")
    try:
        profile = machine(controller, dialect)
    except ValueError as problem:
        raise LaunchError(str(problem)) from None
    scenario = Scenario()
    for path in _paths(arguments.get("stimulus", []), "stimulus"):
        try:
            scenario = merge(scenario, load_scenario(path, profile, dialect))
        except ScenarioFileError as error:
            raise LaunchError(str(error)) from None
        except OSError as error:
            raise LaunchError(f"cannot read {path}: {error.strerror or error}") from None
    if _drives_enabled(arguments.get("drives")):
        scenario = merge(scenario, Scenario(drives=(DrivesEnabled(),)))
    debugging = not _flag(arguments.get("noDebug", False), "noDebug")
    until_ms = arguments.get("untilMs")
    if until_ms is not None and (not isinstance(until_ms, int) or isinstance(until_ms, bool) or until_ms < 0):
        raise LaunchError("'untilMs' is a whole number of simulated milliseconds")
    return Application(
        program,
        source,
        configuration,
        configuration_source,
        controller,
        dialect,
        profile,
        scenario,
        until_ms,
        debugging and _flag(arguments.get("stopOnEntry", False), "stopOnEntry"),
        _plot(arguments.get("plot"), program, configuration),
        debugging,
    )


@record
class Layout:
    """The compiled application: its statements in order and the program's labels (subroutines and event
    handlers, by identity) with the statement each starts at."""

    sites: tuple[Site, ...] = ()
    labels: Mapping[str, int] = field(default_factory=dict)
    columns: tuple[int, ...] = ()  # each statement's 1-based column, so a stop shows which of a line's it is
    # Each IF block's ELSE -> its ENDIF, by pc: the ELSE is the jump that ends the true branch (000:1601-1603),
    # where the block is left, so it is shown and broken at on the ENDIF's line; its own line starts the false branch
    endings: Mapping[int, int] = field(default_factory=dict)
    expressions: ExpressionReader | None = None  # checks a breakpoint's condition as it is set
    refused: str | None = None  # the compiler's message, when it refuses the program or its configuration

    def column(self, pc: int) -> int:
        return self.columns[pc] if pc < len(self.columns) else 1

    def shown(self, pc: int) -> int:
        """The statement a stop before ``pc`` is shown at: the ENDIF for an ELSE, else ``pc`` itself."""
        return self.endings.get(pc, pc)


class _Compiled(Exception):
    def __init__(self, layout: Layout) -> None:
        self.layout = layout


def layout(application: Application) -> Layout:
    """The application as the controller compiles it, from a run stopped before its first tick (breakpoints
    bind to it before the program starts); empty when it cannot be built."""

    def compiled(controller: Controller) -> None:
        sites = tuple(controller.vm.sites)
        labels = dict(controller.linked.handlers)
        columns = _columns(application, sites)
        expressions = ExpressionReader.of(controller, application.dialect)
        endings = {pc: closer for pc, (_, closer) in controller.linked.elses.items()}
        raise _Compiled(Layout(sites, labels, columns, endings, expressions))

    try:
        application.run(compiled)
    except _Compiled as done:
        if any(site.unit == Unit.PROGRAM.value for site in done.layout.sites):
            return done.layout  # the program's statements are there: its compiler took it
        return replace(done.layout, refused=application.refusal())
    except ScenarioFileError as error:  # a REM @sim directive the scenario cannot read
        raise LaunchError(str(error)) from None
    return Layout()


def _columns(application: Application, sites: tuple[Site, ...]) -> tuple[int, ...]:
    """Where each statement starts in its line: found in order along the line as written (1 when a macro's
    expansion is not there to find)."""
    lines = {
        Unit.PROGRAM.value: application.source.splitlines(),
        Unit.CONFIGURATION.value: (application.configuration_source or "").splitlines(),
    }
    columns = []
    searched_from: dict[tuple[str, int], int] = {}
    for site in sites:
        text = lines[site.unit][site.line - 1] if 0 < site.line <= len(lines[site.unit]) else ""
        start = searched_from.get((site.unit, site.line), 0)
        found = text.find(site.text, start) if site.text else -1
        columns.append(found + 1 if found >= 0 else 1)
        if found >= 0:
            searched_from[(site.unit, site.line)] = found + _own_length(site)
    return tuple(columns)


def _own_length(site: Site) -> int:
    """How much of a statement's text is its own: an IF .. THEN's text goes on with the statements after THEN,
    which are sites of their own, found next inside it."""
    then = _THEN.search(site.text) if site.kind == "IfThen" else None
    return then.end() if then is not None else len(site.text)


def _path(value: object, name: str) -> Path | None:
    if value is None:
        return None
    if not isinstance(value, str) or not value:
        raise LaunchError(f"'{name}' is the path of a file")
    if "\0" in value:  # no file name holds one: os.stat would raise ValueError
        raise LaunchError(f"'{name}' {value!r} holds a NUL character: it is no file's path")
    return Path(value)


def _drives_enabled(value: object) -> bool:
    """``drives``: ``"enabled"``, as ``mint-run --drives enabled``, or absent; anything else would leave the drives
    disabled without a word, and the program's first move would stop on error 40."""
    if value is not None and value != "enabled":
        raise LaunchError(f"'drives' is \"enabled\" (every drive enabled at the start) or absent, not {value!r}")
    return value == "enabled"


def _flag(value: object, name: str) -> bool:
    """A true-or-false attribute: a string such as "false" would otherwise be taken as true."""
    if not isinstance(value, bool):
        raise LaunchError(f"'{name}' is true or false, not {value!r}")
    return value


def _plot(value: object, program: Path, configuration: Path | None) -> Path | None:
    """The image to draw the run to, checked as ``mint-run --plot`` checks it (matplotlib, an image type,
    not one of the inputs)."""
    path = _path(value, "plot")
    if path is None:
        return None
    inputs = {program: "the program"} | ({configuration: "the configuration"} if configuration is not None else {})
    try:
        check_plot(path, inputs)
    except (OutputProblem, PlotUnavailable) as problem:
        raise LaunchError(str(problem)) from None
    return path


def _paths(value: object, name: str) -> list[Path]:
    items = [value] if isinstance(value, str) else value
    if not isinstance(items, list):
        raise LaunchError(f"'{name}' is a path or a list of paths")
    return [path for item in items if (path := _path(item, name)) is not None]


def _read(path: Path, role: str) -> str:
    try:
        file = read_source(path)
    except OSError as error:
        raise LaunchError(f"cannot read {role} {path}: {error.strerror or error}") from None
    if (binary := file.binary()) is not None:
        raise LaunchError(f"{binary}: not run")
    return file.text


def _given(setting: Given[Any], fallback: object) -> Any:
    """A setting the settings file gives, else ``fallback`` (the settings' own default is not a choice)."""
    return str(setting.value) if setting.chosen else fallback


def _configuration(program: Path, arguments: Mapping[str, Any], settings: FileSettings) -> Path | None:
    """``config``, else the configuration paired with the program as mint-run and the editor pair it."""
    named = _path(arguments.get("config"), "config")
    if _flag(arguments.get("noConfig", False), "noConfig"):
        if named is not None:
            raise LaunchError("'config' names a configuration file and 'noConfig' runs none: give one")
        return None
    if named is not None:
        if named.resolve() == program.resolve():
            raise LaunchError(f"'config' {named} is the program itself: name the configuration file")
        return named
    unit, other = settings.partner(program)
    return other if unit is Unit.PROGRAM else None


def _dialect(value: object, source: str) -> Dialect:
    if value == AUTO:
        return detect_dialect(source)
    if value not in {dialect.value for dialect in SIMULATED}:
        choices = ", ".join([AUTO, *(dialect.value for dialect in SIMULATED)])
        raise LaunchError(f"'dialect' {value!r} is not one of {choices}")
    return Dialect(str(value))
