"""What ``mint-run`` does once its command line is read (``cli`` declares the command line).

Kept apart so that ``mint-run --help`` and ``--version`` load neither the simulator nor rich.
"""

from __future__ import annotations

import io
import os
import signal
import sys
import time
from collections.abc import Callable, Iterator
from contextlib import AbstractContextManager, contextmanager, nullcontext
from functools import partial
from pathlib import Path
from types import FrameType
from typing import IO, TYPE_CHECKING, NoReturn

import click

from mintlang.cli.files import program_as_own_configuration
from mintlang.cli.options import refuse_quiet_and_verbose
from mintlang.cli.report import shortened
from mintlang.cli.settings import option_chosen, settings_failed
from mintlang.cli.terminal import BROKEN_PIPE, Messages, discard_standard_output
from mintlang.controllers import ControllerProfile
from mintlang.detection import dialect_hint
from mintlang.dialect import Dialect
from mintlang.runtime import scenario as scenarios
from mintlang.runtime.comms import V3_READS_NO_HOST, PortUnavailable
from mintlang.runtime.controller import Controller
from mintlang.runtime.hardware import machine
from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.keyboard import StandardInput, is_terminal, reads_keys, standard_input
from mintlang.runtime.report import as_json
from mintlang.runtime.run import RunResult, run_source
from mintlang.runtime.scenario import ScenarioFileError, all_held, expectations_pass, merge
from mintlang.runtime.scenario.stimulus import DrivesEnabled, Scenario
from mintlang.runtime.simulation import KEYS_NONE_TYPES, Interrupt, Limits
from mintlang.semantic.units import Unit
from mintlang.settings import SettingsError, settings_for
from mintlang.source import read_source

if TYPE_CHECKING:
    from rich.console import Console
    from rich.progress import Progress, TaskID

    from mintlang.runtime.trace import Trace

_USAGE_ERROR = 2
_FAILED = 1
_INTERRUPTED = 130  # 128 + SIGINT: what a shell reports for a program Ctrl-C ended
_TERMINATED = 143  # 128 + SIGTERM: what a shell reports for a program a supervisor (kill, systemd) ended
_TERMINATED_MESSAGE = "terminated (SIGTERM)"
_TRACE_AXES = "'--trace-axes'"
_PROGRESS_STEP_MS = 100  # simulated time between updates of the progress bar


def _axes_list(text: str | None, controller: ControllerProfile) -> tuple[int, ...] | None:
    """The axes ``--trace-axes`` names, each one the controller has, once."""
    if text is None:
        return None
    try:
        axes = tuple(int(part) for part in text.split(",") if part.strip())
    except ValueError:
        raise click.BadParameter("a comma-separated list of axis numbers, e.g. 0,1", param_hint=_TRACE_AXES) from None
    for axis in axes:
        if axis not in controller.axes:
            message = f"axis {axis}: the {controller.title} has axes {controller.axes}"
            raise click.BadParameter(message, param_hint=_TRACE_AXES)
    if not axes:
        raise click.BadParameter("name at least one axis, e.g. 0", param_hint=_TRACE_AXES)
    if len(set(axes)) != len(axes):
        raise click.BadParameter(f"{text!r} names an axis twice", param_hint=_TRACE_AXES)
    return axes


def execute(  # noqa: PLR0917 - click passes every option as an argument
    program: Path,
    config_path: Path | None,
    no_config: bool,
    dialect: str,
    controller: str | None,
    stimulus_paths: tuple[Path, ...],
    expect_paths: tuple[Path, ...],
    drives: str | None,
    until_ms: int | None,
    max_wall_s: float,
    trace_path: Path | None,
    plot_path: Path | None,
    trace_axes: str | None,
    report_format: str | None,
    report_path: Path | None,
    realtime: bool,
    host_port: int | None,
    exit_zero: bool,
    quiet: bool,
    verbose: bool,
    color: str,
) -> None:
    """Run the program as ``run`` was asked to (its docstring says what the run does)."""
    refuse_quiet_and_verbose(quiet, verbose)
    progress = not quiet and sys.stderr.isatty()
    errors = Messages(color, stderr=True, rich=progress)
    if config_path is not None and program_as_own_configuration([program], config_path):
        raise click.UsageError(f"--config {config_path} is the program {program} itself: name the configuration file")
    config_path = _configuration(program, config_path, no_config=no_config)
    try:
        simulated = machine(controller, dialect)
    except ValueError as problem:
        raise click.UsageError(str(problem)) from None
    if host_port is not None and Dialect(dialect) is Dialect.V3:
        raise click.UsageError(f"--host-port: {V3_READS_NO_HOST}")
    try:
        files = [read_source(path) for path in (program, config_path) if path is not None]
    except OSError as error:
        _unreadable(error)
    for file in files:
        if (binary := file.binary()) is not None:
            click.echo(f"mint-run: {binary}: not run", err=True)
            sys.exit(_USAGE_ERROR)
    source, config = files[0].text, files[1].text if len(files) > 1 else None
    dialect_chosen = option_chosen(click.get_current_context(), "dialect")
    # before the scenario is read: an expectation v4 refuses (SUSPEND(0), a MintMT reading) is why the hint is needed
    if not (quiet or dialect_chosen) and (hint := dialect_hint(str(program), source, Dialect(dialect))) is not None:
        click.echo(hint, err=True)
    try:
        scenario = _scenario((*stimulus_paths, *expect_paths), simulated, Dialect(dialect))
        if drives == "enabled":
            scenario = merge(scenario, Scenario(drives=(DrivesEnabled(),)))
    except ScenarioFileError as error:
        _scenario_problems(error)
    except OSError as error:
        _unreadable(error)
    # keys typed as the run goes: each write shows at once, and no progress bar holds back the prompt's line
    typing = is_terminal() and reads_keys([file.text for file in files], Dialect(dialect))
    progress = progress and not typing
    inputs = dict.fromkeys((*stimulus_paths, *expect_paths), "a scenario file")
    if config_path is not None:
        inputs[config_path] = "the configuration"
    inputs[program] = "the program"
    _check_outputs(trace_path, plot_path, report_path, inputs)
    tracing = trace_path is not None or plot_path is not None
    limits = Limits(
        until_ms=until_ms,
        max_wall_s=max_wall_s,
        realtime=realtime,
        every_tick=tracing,
        host_port=host_port,
        end_when_checked=bool(expect_paths),
    )
    if trace_axes is not None and not tracing:
        raise click.UsageError("--trace-axes chooses the axes of --trace or --plot; give one of them")
    chosen = _axes_list(trace_axes, simulated)
    axes = chosen or tuple(range(simulated.axis_count))
    plotting = plot_path is not None
    trace = _trace(axes, trace_path, plotting=plotting, chosen=chosen is not None) if tracing else None
    termination = _Termination()
    recorders = _Recorders(trace, termination, errors, until_ms, progress=progress)
    stdout = _Stdout(live=realtime or host_port is not None or typing)
    simulate = partial(
        run_source,
        source,
        config=config,
        controller=controller,
        dialect=dialect,
        scenario=scenario,
        limits=limits,
        echo=stdout.write,
        on_tick=recorders.on_tick,
        name=str(program),
        config_name=str(config_path),
    )
    with _on_sigterm(termination):
        with (
            standard_input(stdout.flush, terminal=typing) as keyboard,
            _trace_open(trace),
            recorders.shown_progress(),
        ):
            started = time.perf_counter()
            result = _simulate(partial(simulate, on_start=partial(_attach_keyboard, keyboard)), termination)
            wall_s = time.perf_counter() - started
        stdout.flush()
        stdout.end_line_for_errors()
        if not quiet:
            for note in (*result.read_leniently, *result.ignored_directives, *result.not_run):
                errors.line(f"warning: {note}", "yellow")
        if not (quiet and result.stop.reason in (StopReason.END, StopReason.UNTIL)):
            _describe_stop(result, errors, config_path)
        if keyboard is None and result.stop.reason is StopReason.DEADLOCK and KEYS_NONE_TYPES in result.stop.message:
            # standard input closed or not there: a user is told what works
            errors.line("hint: keys can be piped to standard input: printf '42\\n' | mint-run PROGRAM", "yellow")
        if verbose:
            ratio = f" ({result.stop.time_ms / 1000 / wall_s:.1f}x real time)" if wall_s > 0 else ""
            errors.line(f"simulated {result.stop.time_ms} ms in {wall_s:.2f} s{ratio}")
        if result.outcomes:
            # the lazy name: rich, for expectations only
            scenarios.render_outcomes(result.outcomes, errors.console, result.stop.reason.value)
        _report(result, report_format, report_path)
        title = f"{program.name} on {simulated.title}, {result.stop.reason.value} after {result.stop.time_ms} ms"
        _outputs(trace, plot_path, title)  # after the report, so an output that fails does not take the results with it
    status = _exit_status(result, stdout.closed, termination.received, expect=bool(expect_paths))
    sys.exit(0 if status == _FAILED and exit_zero else status)


def _attach_keyboard(keyboard: StandardInput | None, controller: Controller) -> None:
    """Keys piped to standard input reach ``INPUT`` and ``INKEY`` (after the scenario's, in order of need)."""
    controller.terminal.keyboard = keyboard


def _configuration(program: Path, config_path: Path | None, *, no_config: bool) -> Path | None:
    """The configuration file run first: ``--config``, else the one the settings file names or pairs with the
    program as ``mint check`` and the editor do (``mintlang.pairing``); none with ``--no-config``."""
    if no_config:
        if config_path is not None:
            raise click.UsageError("--config names the configuration file and --no-config runs none: give one")
        return None
    if config_path is not None:
        return config_path
    try:
        unit, other = settings_for(program).partner(program)
    except SettingsError as error:
        settings_failed("mint-run", error)
    return other if unit is Unit.PROGRAM else None


def _unreadable(error: OSError) -> NoReturn:
    """A file the run needs (the program, its configuration, a scenario) cannot be read: a usage error."""
    click.echo(f"mint-run: cannot read {error.filename}: {error.strerror or error}", err=True)
    sys.exit(_USAGE_ERROR)


def _scenario_problems(error: ScenarioFileError) -> NoReturn:
    """Every mistake of the scenario, each on a line of its own that names the tool; a usage error."""
    for problem in error.errors:
        click.echo(f"mint-run: {problem}", err=True)
    sys.exit(_USAGE_ERROR)


def _simulate(simulate: Callable[[], RunResult], termination: _Termination) -> RunResult:
    """The run's result; a problem found as it starts (a directive, the host port) is a usage error.

    SIGTERM ends the run only until ``run_source`` returns; after, it waits for the outputs.
    """
    try:
        return simulate()
    except ScenarioFileError as error:
        _scenario_problems(error)
    except PortUnavailable as error:
        click.echo(f"mint-run: {error}", err=True)
        sys.exit(_USAGE_ERROR)
    except _Terminated:  # SIGTERM after the simulator stopped, before the result came back: no result to report
        click.echo(f"mint-run: {_TERMINATED_MESSAGE}", err=True)
        sys.exit(_TERMINATED)
    finally:
        termination.running = False


def _exit_status(result: RunResult, stdout_closed: bool, terminated: bool, *, expect: bool) -> int:
    reason = result.stop.reason
    if terminated:
        if reason is not StopReason.INTERRUPTED:  # it came once the run had ended, as the outputs were written
            click.echo(f"mint-run: {_TERMINATED_MESSAGE}", err=True)
        return _TERMINATED
    if reason is StopReason.INTERRUPTED:
        return BROKEN_PIPE if stdout_closed else _INTERRUPTED
    if expect:
        if not result.outcomes:
            click.echo(
                "mint-run: no expectations to check: --expect needs [[expect]] entries or REM @expect lines", err=True
            )
        return 0 if expectations_pass(result.outcomes, reason.value) else _FAILED
    normal = reason in (StopReason.END, StopReason.UNTIL)
    return 0 if normal and all_held(result.outcomes) else _FAILED


class _Terminated(Interrupt):
    """SIGTERM came: the simulator stops the run as for any ``Interrupt``."""

    def __init__(self) -> None:
        super().__init__(_TERMINATED_MESSAGE)


class _Termination:
    """SIGTERM, handled as Ctrl-C is: the run stops where it is, and its report and trace still come out.

    The signal raises ``_Terminated``, which the simulator turns into the stop,
    only while the simulator runs: one that comes before the first tick stops
    the run at that tick, and one that comes after waits for the outputs.
    """

    def __init__(self) -> None:
        self.received = False
        self.running = False

    def __call__(self, _signal: int, _frame: FrameType | None) -> None:
        self.received = True
        if self.running:
            self.running = False  # a second SIGTERM must not break off the stopping of the run
            raise _Terminated

    def at_tick(self) -> None:
        """A tick was processed: the run is under way, and ends now if SIGTERM came while it compiled."""
        if self.received:
            raise _Terminated
        self.running = True


@contextmanager
def _on_sigterm(termination: _Termination) -> Iterator[None]:
    previous = signal.signal(signal.SIGTERM, termination)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


@contextmanager
def _trace_open(trace: Trace | None) -> Iterator[None]:
    """The trace file open for the run and closed however it ends, so it holds every row taken."""
    if trace is None:
        yield
        return
    try:
        trace.open()
    except OSError as error:
        _cannot_write(trace.csv_path, error)
    try:
        yield
    finally:
        trace.close()


def _report(result: RunResult, report_format: str | None, report_path: Path | None) -> None:
    if report_format is None and report_path is None:
        return
    import json  # noqa: PLC0415 - only a run asked for its report writes JSON

    report = json.dumps(as_json(result), indent=2)
    if report_format == "json":
        if result.terminal and not result.terminal.endswith("\n"):
            click.echo()
        click.echo(report)
    if report_path is not None:
        try:
            report_path.write_text(f"{report}\n", encoding="utf-8")
        except OSError as error:
            _cannot_write(report_path, error)


def _outputs(trace: Trace | None, plot_path: Path | None, title: str) -> None:
    if trace is None:
        return
    if trace.failure is not None:
        _cannot_write(trace.csv_path, trace.failure)
    if plot_path is not None:
        try:
            trace.plot(plot_path, title)
        except OSError as error:
            _cannot_write(plot_path, error)


def _cannot_write(path: Path | None, error: OSError) -> NoReturn:
    click.echo(f"mint-run: cannot write {path}: {error.strerror or error}", err=True)
    sys.exit(_USAGE_ERROR)


class _Stdout:
    """Where the program's terminal output streams; a reader that goes away (``| head``) ends the run quietly.

    A ``live`` run (paced to real time, or talking to a host) is watched as it
    happens, so each write is flushed even into a pipe (``| tee log``); a fast
    run keeps the pipe's buffering, which a program printing in a loop needs.
    """

    def __init__(self, *, live: bool) -> None:
        self.closed = False
        self.live = live
        self.open_line = False  # the last text written left the cursor after it (PRINT "a",)
        if isinstance(sys.stdout, io.TextIOWrapper):
            # a character the output's encoding lacks (PRINT CHR(129) to cp1252, CHR(233) to ASCII) shows as '?',
            # as on a terminal without the glyph, instead of ending the run with a traceback
            sys.stdout.reconfigure(errors="replace")

    def write(self, text: str) -> None:
        if text:
            self.open_line = not text.endswith(("\n", "\r"))
        try:
            sys.stdout.write(text)
            if self.live:
                sys.stdout.flush()
        except BrokenPipeError:
            self.close()
            raise Interrupt("stdout was closed (broken pipe)") from None

    def flush(self) -> None:
        try:
            sys.stdout.flush()
        except BrokenPipeError:
            self.close()

    def end_line_for_errors(self) -> None:
        """Where standard error goes where this output goes (one terminal, log or pipe), a line the program left
        open is ended there, so that the tool's own lines start on lines of their own; the output alone is left
        as the program wrote it."""
        if self.open_line and not self.closed and _same_stream(sys.stdout, sys.stderr):
            sys.stderr.write("\n")
            self.open_line = False

    def close(self) -> None:
        """Send what is still to come (buffered output, the JSON report) nowhere, without another error at exit."""
        self.closed = True
        discard_standard_output()


def _same_stream(first: IO[str], second: IO[str]) -> bool:
    """Whether two streams reach the same terminal, file or pipe."""
    try:
        return os.path.samestat(os.fstat(first.fileno()), os.fstat(second.fileno()))
    except (OSError, ValueError, io.UnsupportedOperation):  # not a file: a test's capture, a closed stream
        return False


def _scenario(paths: tuple[Path, ...], controller: ControllerProfile, dialect: Dialect) -> Scenario:
    scenario = Scenario()
    for path in paths:
        scenario = merge(scenario, scenarios.load_scenario(path, controller, dialect))  # the TOML reader, when used
    return scenario


class _Recorders:
    """The per-tick observers of a run: SIGTERM, the trace and the progress bar (on a terminal, unless quiet)."""

    def __init__(
        self, trace: Trace | None, termination: _Termination, errors: Messages, until_ms: int | None, *, progress: bool
    ) -> None:
        self.trace = trace
        self.termination = termination
        self.errors = errors
        self.bar = _progress_bar(errors.console, until_ms) if progress else None
        self.shown = 0

    def shown_progress(self) -> AbstractContextManager[object]:
        """The progress bar on the screen while the run lasts (nothing without one)."""
        return self.bar[0] if self.bar is not None else nullcontext()

    def on_tick(self, controller: Controller, tick: int) -> None:
        if tick == 0 and controller.server is not None:
            self.errors.line(f"host port: 127.0.0.1:{controller.server.port}")
        if self.trace is not None:
            self.trace.record(controller, tick)
        if self.bar is not None and tick - self.shown >= _PROGRESS_STEP_MS:
            self.shown = tick
            progress, task = self.bar
            progress.update(task, completed=tick)
        self.termination.at_tick()  # last, so a SIGTERM that came before the run still has its first tick traced


def _progress_bar(console: Console, until_ms: int | None) -> tuple[Progress, TaskID]:
    """The run's simulated time: a bar toward --until-ms, a pulse when the run has no bound in simulated time."""
    from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn  # noqa: PLC0415 - a terminal's only

    progress = Progress(
        TextColumn("simulated {task.completed:.0f} ms"),
        BarColumn(),
        TimeElapsedColumn(),
        console=console,
        transient=True,
        # on one screen, what the program prints goes above the bar; piped, it goes to its file untouched
        redirect_stdout=sys.stdout.isatty(),
        redirect_stderr=False,
    )
    return progress, progress.add_task("run", total=until_ms)


def _trace(axes: tuple[int, ...], csv_path: Path | None, *, plotting: bool, chosen: bool) -> Trace:
    """The trace of a run with --trace or --plot."""
    from mintlang.runtime.trace import Trace  # noqa: PLC0415 - imported by such a run alone, as in _check_outputs

    return Trace(axes, csv_path, plotting=plotting, chosen=chosen)


def _check_outputs(
    trace_path: Path | None, plot_path: Path | None, report_path: Path | None, inputs: dict[Path, str]
) -> None:
    """Refuse, before the run, an output that cannot be written or would replace an input (path to its role)."""
    if trace_path is None and plot_path is None and report_path is None:
        return
    # the checks and the trace's modules (csv, the plot's optional matplotlib): for a run that writes an output
    from mintlang.runtime.outputs import OutputProblem, check_plot, check_report, check_trace  # noqa: PLC0415
    from mintlang.runtime.trace import PlotUnavailable  # noqa: PLC0415

    try:
        if trace_path is not None:
            check_trace(trace_path, inputs)
            inputs[trace_path] = "the --trace file"
        if plot_path is not None:
            check_plot(plot_path, inputs)
            inputs[plot_path] = "the --plot file"
        if report_path is not None:
            check_report(report_path, inputs)
    except (OutputProblem, PlotUnavailable) as problem:
        click.echo(f"mint-run: {problem}", err=True)
        sys.exit(_USAGE_ERROR)


def _describe_stop(result: RunResult, errors: Messages, config_path: Path | None) -> None:
    """The stop line; the statement and message are the program's text, so they are never read as markup. A stop
    in the configuration names its file, which may be the one paired with the program rather than one named."""
    stop = result.stop
    style = "green" if stop.reason in (StopReason.END, StopReason.UNTIL) else "bold red"
    line = f"{stop.reason.value} after {stop.time_ms} ms"
    if stop.line is not None:
        file = f" ({config_path})" if stop.unit == Unit.CONFIGURATION and config_path is not None else ""
        line += f" at {stop.unit} line {stop.line}{file}: {shortened(stop.statement or '')}"
    if stop.message:
        line += f" — {stop.message}"
    errors.line(line, style)
