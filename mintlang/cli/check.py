"""``mint check``: the static analyser on the command line.

Files are checked on all cores (``-j``), and reported in the order they were
found whatever the number of processes. A file that cannot be read (a link
loop, a pipe, a file deleted meanwhile) is reported on standard error with its
path, and the others are still checked and reported; a machine-readable report
also lists it as a finding (W120), as ruff lists E902.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path
from typing import IO, NoReturn

import click

from mintlang.cli.applications import plan
from mintlang.cli.checking import Checked, check_file
from mintlang.cli.files import Unchecked, cannot_read, find, program_as_own_configuration, unread
from mintlang.cli.fixing import Fixing, Outcome, apply, fix_options, fixable_summary, fixed_summary, marked
from mintlang.cli.options import (
    HELP_OPTIONS,
    V3_CHECKED,
    color_option,
    controller_option,
    exclude_options,
    exit_zero_option,
    format_option,
    jobs_option,
    list_option,
    output_file_option,
    refuse_quiet_and_verbose,
    refuse_settings_file,
    verbosity_options,
    version_option,
)
from mintlang.cli.parallel import all_cores, map_in_order
from mintlang.cli.report import (
    FileReport,
    as_github,
    as_json,
    as_sarif,
    as_statistics,
    render_concise,
    render_text,
)
from mintlang.cli.settings import describe, overrides, settings_failed, typed, whole_settings
from mintlang.cli.terminal import (
    colour_console,
    console,
    destination,
    reader_may_leave,
    refuse_overwriting,
    write_in_pieces,
)
from mintlang.codes import own, selector
from mintlang.diagnostics import Severity, Span
from mintlang.dialect import Dialect
from mintlang.settings import Overrides, SettingsError, force_excluded, settings_for
from mintlang.source import SourceFile, read_source, read_stdin

_FOUND_ERRORS = 1
_NOT_DONE = 2
_INTERRUPTED = 130  # 128 + SIGINT, as a shell reports a command Ctrl-C ended
_STDIN = Path("-")
_FOR_PEOPLE = ("text", "concise")  # the formats with a closing count and fix summary, and no W120 entries
NOT_CHECKED = "W120"

SELECT_HELP = (
    "Only these codes or code prefixes; comma-separated or repeated. Default: E,W (the hints need --select I)."
    " Errors have four digits, as the controller prints them: a prefix selects by them (E2 is E2000-E2021, E00"
    " the errors below 100). The manual's short spelling names one error where it begins no code (E17 is E0017);"
    " E2, E3, E20 and E30 are prefixes: write E0002. ALL is every code."
)

EXIT_STATUS = """\b
Exit status:
  0  no finding of error severity (or --exit-zero)
  1  a finding of error severity (with --fix: left after fixing;
     with --diff: a fix to make)
  2  a usage problem, or a file that could not be checked or fixed
     (the others are checked and reported all the same)
  130  interrupted (Ctrl-C)
  141  the reader of standard output went away (| head)"""


def _codes(values: tuple[str, ...] | None, option: str) -> tuple[str, ...] | None:
    """The codes or prefixes of ``--select``/``--ignore``; a typo would silently hide findings, so none passes."""
    if values is None:
        return None
    if not values:
        raise click.BadParameter("give at least one code or prefix (E0002, E2, W103 ...)", param_hint=option)
    try:
        return tuple(selector(value) for value in values)
    except ValueError as error:
        raise click.BadParameter(str(error), param_hint=option) from None


def _fail(message: str) -> NoReturn:
    click.echo(f"mint check: {message}", err=True)
    sys.exit(_NOT_DONE)


def _explain(context: click.Context, _parameter: click.Parameter, code: str | None) -> None:
    """``--explain CODE``: what ``mint rule CODE`` prints, for a ruff user's hands, and nothing checked; an
    unknown code is an error of ``mint check``, the command the user ran."""
    if code is None or context.resilient_parsing:
        return
    from mintlang.cli.rule import explain  # noqa: PLC0415 - mint rule's command is loaded only when asked for

    explain(code, "mint check")
    context.exit()


@click.command(context_settings=HELP_OPTIONS, epilog=EXIT_STATUS)
@click.argument("paths", nargs=-1, type=click.Path(path_type=Path))
@version_option("mint check")
@click.option(
    "--explain",
    metavar="CODE",
    is_eager=True,
    expose_value=False,
    callback=_explain,
    help="Explain a code (E2016, W103) as mint rule does, and check nothing.",
)
@click.option("--dialect", type=click.Choice([d.value for d in Dialect]), default="v4", show_default=True)
@controller_option("The controller the programs run on.")
@click.option(
    "--config",
    "config_path",
    type=click.Path(path_type=Path),
    help="Configuration file whose variables and macros the programs see (instead of each program's paired one).",
    callback=refuse_settings_file,
)
@click.option(
    "--no-config",
    is_flag=True,
    help="Pair no configuration file with the programs (by default <name>.cfg beside <name>.mnt, any case).",
)
@click.option(
    "--show-settings",
    is_flag=True,
    help="Print the settings that apply to each file (and where each comes from), and check nothing.",
)
@format_option([*_FOR_PEOPLE, "json", "sarif", "github"])
@output_file_option()
@list_option("--select", absent=None, help=SELECT_HELP)
@list_option("--extend-select", absent=None, help="Also these codes or code prefixes, besides those selected.")
@list_option("--ignore", absent=None, help="Leave out these codes or code prefixes; comma-separated or repeated.")
@exclude_options()
@click.option(
    "--statistics", is_flag=True, help="Count the findings of each code instead of showing each (text, json)."
)
@exit_zero_option("Exit with 0 even when errors are found (a file that could not be checked still exits with 2).")
@click.option(
    "--stdin-filename",
    help="The name under which the program read from standard input (the path -) is reported.",
)
@jobs_option("Check this many files at once, each in a process of its own.  [default: 0, all cores]")
@click.option(
    "-w",
    "--watch",
    is_flag=True,
    help="Check again whenever a program, configuration or settings file changes, until Ctrl-C (as ruff's).",
)
@verbosity_options(
    quiet="Only the findings: no closing count, no progress bar.",
    verbose="Say on standard error how many files were checked, on how many processes, in how long.",
)
@color_option()
@fix_options()
@reader_may_leave()
def check(
    paths: tuple[Path, ...],
    dialect: str,
    controller: str,
    config_path: Path | None,
    no_config: bool,
    show_settings: bool,
    output_format: str,
    output_file: Path | None,
    select: tuple[str, ...] | None,
    extend_select: tuple[str, ...] | None,
    ignore: tuple[str, ...] | None,
    exclude: tuple[str, ...] | None,
    extend_exclude: tuple[str, ...] | None,
    force_exclude: bool | None,
    statistics: bool,
    exit_zero: bool,
    stdin_filename: str | None,
    jobs: int,
    watch: bool,
    quiet: bool,
    verbose: bool,
    color: str,
    fix: bool,
    unsafe_fixes: bool,
    diff: bool,
    add_ignore: bool,
) -> None:
    """Check Mint programs for the errors the controller finds, and more.

    PATHS are programs (.mnt), configuration files (.cfg) and directories, searched for programs (the current
    directory if none is given); - reads the program from standard input. Each program is checked with the
    configuration file beside it, and each file under the nearest mint.toml or pyproject.toml [tool.mint] above
    it; the options here win over that file.
    """
    started = time.perf_counter()
    paths = paths or (Path(),)  # as ruff and mint test do
    refuse_quiet_and_verbose(quiet, verbose)
    if statistics and output_format not in (*_FOR_PEOPLE, "json"):
        raise click.UsageError(f"--statistics is written as text or json, not {output_format}")
    context = click.get_current_context()
    if dialect == Dialect.V3 and typed(context, "dialect") and typed(context, "controller"):
        raise click.UsageError(
            f"--controller {controller} is a Mint v4 controller: mint check --dialect v3 {V3_CHECKED}"
        )
    layer = overrides(
        context,
        select=_codes(select, "--select"),
        extend_select=_codes(extend_select, "--extend-select"),
        ignore=_codes(ignore, "--ignore"),
        config_path=config_path,
        no_config=no_config,
        exclude=exclude,
        extend_exclude=extend_exclude,
        force_exclude=force_exclude,
    )
    found = find((path for path in paths if path != _STDIN), overrides=layer)
    _configuration(config_path)  # a --config that cannot be read ends the command before any check
    if config_path is not None and (itself := program_as_own_configuration(found.files, config_path)) is not None:
        _fail(f"--config {config_path} is the program {itself} itself: name the configuration file")
    if fix and not diff and _STDIN in paths:
        raise click.UsageError("--fix writes files, and standard input is none: use --diff to see the fixes")
    if add_ignore and (fix or diff or unsafe_fixes or _STDIN in paths):
        raise click.UsageError("--add-ignore writes comments into the programs: give files, without --fix or --diff")
    if _STDIN not in paths and stdin_filename is not None:
        raise click.UsageError("--stdin-filename names the program read from standard input: give - as a path")
    if watch:
        _watch(context, paths, layer, add_ignore=add_ignore, show_settings=show_settings)
        return
    excluded = found.excluded
    try:
        if show_settings:
            named = [*([Path(stdin_filename or "-")] if _STDIN in paths else []), *found.files]
            _show_settings(named, layer, [cannot_read(error) for error in found.unreadable])
        reading = _STDIN in paths
        if reading and stdin_filename is not None and force_excluded(Path(stdin_filename), layer):
            reading, excluded = False, [*excluded, Path(stdin_filename)]  # an editor's buffer of an excluded file
        planned = plan(found.files, layer, read_stdin(stdin_filename) if reading else None)
    except SettingsError as error:
        settings_failed("mint check", error)
    refuse_overwriting(output_file, found.files, _fail)
    fixing = Fixing.asked(fix, unsafe_fixes, diff, add_ignore=add_ignore)
    work = marked(planned.jobs, planned.hidden, fixing) if fixing is not None else planned.jobs
    if planned.empty and not found.unreadable and not planned.problems:
        if output_format not in _FOR_PEOPLE and not diff:  # a tool reading the report still gets one, empty
            with destination(output_file, _fail) as stream:
                _write([], stream, output_format, statistics=statistics, quiet=quiet, color=color)
        if excluded:  # pre-commit names files the project excludes: nothing to check, no failure (ruff's)
            if not quiet:
                click.echo(
                    "mint check: nothing to check: force-exclude leaves out " + ", ".join(map(str, excluded)),
                    err=True,
                )
            sys.exit(0)
        _fail("no .mnt files found in " + ", ".join(str(p) for p in paths))

    workers = jobs or all_cores()
    progress = console(color, stderr=True) if not quiet and sys.stderr.isatty() else None
    try:
        results = map_in_order(check_file, work, workers=workers, progress=progress)
    except KeyboardInterrupt:  # click would say 'Aborted!' and exit with 1, which means errors found
        click.echo("mint check: interrupted", err=True)
        sys.exit(_INTERRUPTED)
    unchecked = [unread(e) for e in found.unreadable] + planned.problems + [r.problem for r in results if r.problem]
    problems = [item.said for item in unchecked]
    configurations = planned.configuration_reports(results)
    silenced = planned.silenced_configurations(configurations) if fixing is Fixing.SILENCE else {}
    fixed = [result.fixed for result in results if result.fixed is not None] + list(silenced.values())
    outcome, unwritten = None, set[Path]()
    if diff:  # the changes instead of the report, as ruff's --diff
        with destination(output_file, _fail) as stream:
            outcome = apply(fixed, diff=stream)
    elif fixing is not None:
        outcome = apply(fixed, diff=None)
        problems += outcome.problems
        unwritten = outcome.unwritten  # a fix not written leaves the file's findings where they were
        results = [r.unfixed() if r.fixed and r.fixed.original.path in unwritten else r for r in results]
    for key, file in silenced.items():  # a configuration file written reports what its new text has left
        if file.original.path not in unwritten:
            configurations[key] = FileReport(str(file.original.path), file.fixed.text, file.fixed.remaining)
    reports = planned.reports(results, configurations)
    entries = _entries(unchecked, layer) if output_format not in _FOR_PEOPLE else []
    if (reports or entries or output_format not in _FOR_PEOPLE) and not diff:  # a machine format's empty report too
        with destination(output_file, _fail) as stream:
            _write(reports + entries, stream, output_format, statistics=statistics, quiet=quiet, color=color)
            if output_format in _FOR_PEOPLE and not quiet and not statistics:
                _write_fix_summary(
                    planned.program_reports(results), outcome, stream, silencing=add_ignore, unsafe_fixes=unsafe_fixes
                )
    if outcome is not None and not quiet:
        summary = fixed_summary(outcome, diff=diff, silencing=add_ignore)
        notes = outcome.notes() + ([summary] if diff or output_format not in _FOR_PEOPLE else [])
        if diff:  # what the diff leaves, as the text report tells it after --fix
            notes += fixable_summary(planned.program_reports(results), unsafe_fixes=unsafe_fixes)
        click.echo("".join(f"mint check: {note}\n" for note in notes), err=True, nl=False)
    if not quiet:
        click.echo("".join(f"{hint}\n" for hint in _hints(results, planned.hidden)), err=True, nl=False)
    for problem in problems:
        click.echo(f"mint check: {problem}", err=True)
    if verbose:
        elapsed = time.perf_counter() - started
        processes = min(workers, len(work)) or 1
        click.echo(
            f"mint check: {len(reports)} of {len(reports) + len(unchecked)} files checked "
            f"on {processes} process{'es' if processes != 1 else ''} in {elapsed:.2f} s",
            err=True,
        )
    if diff:  # exit 1: there is something to fix
        failed = outcome is not None and bool(outcome.codes)
    else:
        failed = any(d.severity is Severity.ERROR for report in reports for d in report.diagnostics)
    sys.exit(_NOT_DONE if problems else _FOUND_ERRORS if failed and not exit_zero else 0)


def _watch(
    context: click.Context, paths: tuple[Path, ...], layer: Overrides, *, add_ignore: bool, show_settings: bool
) -> None:
    """The check of ``paths`` again each time one of their files changes (``--watch``)."""
    from mintlang.cli.watching import seen, watch  # noqa: PLC0415 - --watch alone needs it

    for asked, option in (
        (_STDIN in paths, "standard input"),
        (add_ignore, "--add-ignore"),
        (show_settings, "--show-settings"),
    ):
        if asked:
            raise click.UsageError(f"--watch checks files as they change: not with {option}")

    def check_once() -> int:
        try:
            context.invoke(check, **{**context.params, "watch": False})
        except SystemExit as done:
            if done.code == _INTERRUPTED:  # Ctrl-C while it checked: the watch ends
                raise KeyboardInterrupt from None
            return done.code if isinstance(done.code, int) else 1
        except click.ClickException as error:  # a settings file saved half-written: said, and watched on
            error.show()
            return error.exit_code
        return 0

    watch(check_once, lambda: seen(paths, layer), clear=sys.stdout.isatty())


def _entries(unchecked: list[Unchecked], layer: Overrides) -> list[FileReport]:
    """The paths not checked, each a finding of its own (W120) for a machine-readable report, as ruff reports
    E902: where the path's settings leave W120 out it is said on standard error only, as ruff then warns.
    No suppression comment reaches it: the file was not read as a program."""
    from mintlang.analysis.analyser import code_selected  # noqa: PLC0415 - only a run with a path not checked needs it

    entries = []
    for item in unchecked:
        try:
            settings = settings_for(Path(item.path), layer)
        except SettingsError as error:
            settings_failed("mint check", error)
        if code_selected(NOT_CHECKED, settings.selected, settings.ignored):
            source = "\n" * (item.line - 1) + " " * (item.column - 1)  # blank text placing the position
            place = Span(len(source), len(source))
            entries.append(FileReport(item.path, source, (own(NOT_CHECKED, place, item.reason),)))
    return entries


def _write_fix_summary(
    programs: list[FileReport], outcome: Outcome | None, stream: IO[str], *, silencing: bool, unsafe_fixes: bool
) -> None:
    """What was fixed (or silenced), and what ``--fix`` (or ``--unsafe-fixes``) would fix of what is left in the
    programs."""
    lines = [fixed_summary(outcome, diff=False, silencing=silencing)] if outcome is not None else []
    stream.write("".join(f"{line}\n" for line in [*lines, *fixable_summary(programs, unsafe_fixes=unsafe_fixes)]))


def _hints(results: list[Checked], hidden: set[int]) -> list[str]:
    """Each reported program's hint that it looks like MintMT, once (on standard error, beside any format)."""
    hints = (result.hint for index, result in enumerate(results) if index not in hidden)
    return list(dict.fromkeys(hint for hint in hints if hint is not None))


def _configuration(path: Path | None) -> SourceFile | None:
    """The ``--config`` file, read; one that cannot be read or is binary ends the command."""
    if path is None:
        return None
    try:
        configuration = read_source(path)
    except OSError as error:
        _fail(cannot_read(error))
    if (binary := configuration.binary()) is not None:
        _fail(f"{binary}: not checked")
    return configuration


def _show_settings(paths: list[Path], layer: Overrides, problems: list[str]) -> NoReturn:
    """``--show-settings``: each file's settings; a path that could not be looked at is said as a check says it."""
    if paths:
        click.echo("\n\n".join("\n".join(describe(path, whole_settings(path, layer))) for path in paths))
    for problem in problems or ([] if paths else ["no .mnt files found"]):
        click.echo(f"mint check: {problem}", err=True)
    sys.exit(_NOT_DONE if problems or not paths else 0)


def _write(
    reports: list[FileReport], stream: IO[str], output_format: str, *, statistics: bool, quiet: bool, color: str
) -> None:
    if statistics:
        text = as_statistics(reports, output_format)
    elif output_format == "json":
        text = as_json(reports)
    elif output_format == "sarif":
        text = as_sarif(reports)
    elif output_format == "github":
        text = as_github(reports)
    else:
        render = render_concise if output_format == "concise" else render_text
        render(reports, stream, colour_console(color, stream), summary=not quiet)
        return
    if text:
        write_in_pieces(stream, f"{text}\n")
