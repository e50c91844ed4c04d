"""What ``mint-migrate`` does once its command line is read (``cli`` declares the command line).

Kept apart so that ``mint-migrate --help`` and ``--version`` load neither the rules nor the simulator.
"""

from __future__ import annotations

import sys
from dataclasses import replace
from functools import partial
from pathlib import Path
from typing import NoReturn

import click
from rich.console import Console
from rich.markup import escape

from mintlang.cli.diffs import unified, write_diff
from mintlang.cli.options import refuse_quiet_and_verbose
from mintlang.cli.settings import exclusions, typed
from mintlang.cli.terminal import console, destination, reader_may_leave, refuse_overwriting, write_in_pieces
from mintlang.migrate import leftovers, mintmt, verifying
from mintlang.migrate.api import UnknownRule, rules, select
from mintlang.migrate.applications import Application, Migrated, UsageError, read
from mintlang.migrate.citations import cite
from mintlang.migrate.report import render_text, report
from mintlang.migrate.verification import Verdict
from mintlang.migrate.verification.report import Verified
from mintlang.migrate.writing import write_changed
from mintlang.records import record
from mintlang.source import SourceFile

GATE_FAILED = 1
NOT_DONE = 2


def _diff(file: SourceFile, text: str) -> str:
    return unified(file.text, text, f"a/{file.path}", f"b/{file.path}")


def _list_rules(console: Console) -> None:
    for info in rules():
        kind = f"{info.rule_class.value}{' (optional)' if info.optional else ''}"
        console.print(f"[bold]{info.id:<14}[/bold] {kind:<21} {info.summary}", highlight=False)
        console.print(f"{'':<36} {cite(info.evidence)}", style="dim", highlight=False)


@reader_may_leave()
def execute(  # noqa: PLR0917 - click passes every option as an argument
    paths: tuple[Path, ...],
    write: bool,
    diff: bool,
    check: bool,
    to_stdout: bool,
    config: Path | None,
    no_config: bool,
    to: str,
    controller: str,
    output_format: str,
    output_file: Path | None,
    fail_on: str | None,
    exit_zero: bool,
    exclude: tuple[str, ...] | None,
    extend_exclude: tuple[str, ...] | None,
    force_exclude: bool | None,
    only: tuple[str, ...],
    skip: tuple[str, ...],
    opt_in: tuple[str, ...],
    list_rules: bool,
    quiet: bool,
    verbose: bool,
    color: str,
    verify: bool,
    scenario_paths: tuple[Path, ...],
    until_ms: int | None,
    v3_controller: str | None,
    drives: str | None,
) -> None:
    """Migrate as ``migrate`` was asked to (its docstring and ``cli.EXIT_STATUS`` say what it does)."""
    refuse_quiet_and_verbose(quiet, verbose)
    if list_rules:
        (_list_rewrites if to == "mintmt" else _list_rules)(console(color))
        return
    try:
        mode = _mode(write=write, diff=diff, check=check, to_stdout=to_stdout, verify=verify)
        if to == "mintmt":
            _refuse_v3_options(only, skip, opt_in, v3_controller)
        options = verifying.Options(scenario_paths, until_ms, v3_controller, drives)
        context = click.get_current_context()
        settings = options.settings(controller, to) if mode == "verify" else options.refuse(partial(typed, context))
        select(only or None, skip, opt_in)
        if no_config and config is not None:
            raise UsageError("--config names the configuration file and --no-config pairs none: give one")
        if not paths and config is None:  # the current folder, as mint check, mint format and mint test search it
            paths = (Path(),)
        found = read(paths, config, paired=not no_config, overrides=exclusions(exclude, extend_exclude, force_exclude))
        applications, unread = found.applications, found.unread
        if mode == "stdout":
            _refuse_more_than_one(applications)
    except (UsageError, UnknownRule) as error:
        _fail(str(error))
    sources = [path for application in applications for path in application.paths()]
    refuse_overwriting(output_file, sources, _fail)
    migrated = [application.migrate(controller, only or None, skip, opt_in, to=to) for application in applications]
    items = [item for application in migrated for item in application]
    problems = [*(path.line for path in unread), *(problem for item in items if (problem := item.entry.problem))]
    items += [path.item for path in unread]
    _tidy(items, mode)
    if settings is not None:
        verified, failed = verifying.verify_all(migrated, settings)
        problems += failed
        with destination(output_file, _fail) as stream:
            verifying.output(
                verified, output_format, console(color, file=stream), quiet=quiet, problems=problems, to=to
            )
        for problem in problems:
            click.echo(f"mint-migrate: {problem}", err=True)
        status = _verify_status(verified, fail_on, problems)
        sys.exit(0 if status == GATE_FAILED and exit_zero else status)
    if mode == "write":
        written = write_changed(migrated)
        problems += written.problems
        items = [_unwritten(item) if Path(item.entry.path) in written.unwritten else item for item in items]
    _output(items, mode, output_format, controller, Output(output_file, quiet, verbose, color, to))
    for problem in problems:
        click.echo(f"mint-migrate: {problem}", err=True)
    status = _status(items, mode, fail_on, problems)
    sys.exit(0 if status == GATE_FAILED and exit_zero else status)


def _refuse_more_than_one(applications: list[Application]) -> None:
    """``--stdout`` prints one file; a program named alone that pairs with a configuration file is two."""
    if sum(len(application.paths()) for application in applications) <= 1:
        return
    if len(applications) == 1 and (pair := applications[0]).program is not None and pair.configuration is not None:
        program, configuration = pair.program.path, pair.configuration.path
        raise UsageError(
            f"--stdout prints one file, and {program} is migrated together with its configuration file "
            f"{configuration} (the controller runs them together): see both with --diff"
        )
    raise UsageError("--stdout prints one file: name one program or one configuration file")


def _list_rewrites(console: Console) -> None:
    for rewrite in (*mintmt.REWRITES, *mintmt.CHECKS):
        console.print(f"[bold]{rewrite.ID:<14}[/bold] {escape(rewrite.SUMMARY)}", highlight=False)


def _refuse_v3_options(
    only: tuple[str, ...], skip: tuple[str, ...], opt_in: tuple[str, ...], v3_controller: str | None
) -> None:
    """``--to mintmt`` has no rules to choose and no Mint v3 original."""
    given = {"--only": only, "--skip": skip, "--with": opt_in, "--v3-controller": v3_controller}
    named = [flag for flag, value in given.items() if value]
    if named:
        raise UsageError(f"{', '.join(named)}: only when migrating from Mint v3 (--to v4)")


def _unwritten(item: Migrated) -> Migrated:
    """``item`` reported as a changed file ``--write`` left as it was."""
    return replace(item, entry=replace(item.entry, written=False))


def _fail(message: str) -> NoReturn:
    click.echo(f"mint-migrate: {message}", err=True)
    sys.exit(NOT_DONE)


def _mode(*, write: bool, diff: bool, check: bool, to_stdout: bool, verify: bool) -> str | None:
    """The one mode asked for (None: the diff, asked for or not): ``--diff --write`` must not
    write, so two are a usage error."""
    modes = (("write", write), ("diff", diff), ("check", check), ("stdout", to_stdout), ("verify", verify))
    given = [name for name, on in modes if on]
    if len(given) > 1:
        raise UsageError(f"{', '.join('--' + name for name in given)}: choose one of these modes")
    return given[0] if given and given[0] != "diff" else None


def _tidy(items: list[Migrated], mode: str | None) -> None:
    """Temporary files an interrupted ``--write`` left beside these files: removed by
    ``--write`` (before anything is written), named by the modes that write nothing."""
    found = leftovers.find(Path(item.entry.path).resolve().parent for item in items)
    for line in leftovers.remove(found) if mode == "write" else leftovers.named(found):
        click.echo(f"mint-migrate: {line}", err=True)


@record
class Output:
    """Where the diff and the report go (standard output, or ``--output-file``), and how they look."""

    path: Path | None
    quiet: bool
    verbose: bool
    color: str
    to: str = "v4"


def _output(items: list[Migrated], mode: str | None, output_format: str, controller: str, output: Output) -> None:
    data = report((item.entry for item in items), controller, to=output.to)
    if mode == "stdout":
        file, result = items[0].file, items[0].entry.result
        if file is not None and result is not None:
            sys.stdout.buffer.write(file.encode(result.text))
            sys.stdout.buffer.flush()
    with destination(output.path, _fail, stderr=mode == "stdout") as stream:
        if mode is None and output_format == "text":
            for item in items:
                if item.file is not None and item.entry.result is not None and item.entry.result.changed:
                    write_diff(stream, _diff(item.file, item.entry.result.text), item.file.encoding)
        if output_format == "json":
            import json  # noqa: PLC0415 - the text report, the default, needs none

            write_in_pieces(stream, json.dumps(data, indent=2, ensure_ascii=False) + "\n")
        else:
            render_text(data, console(output.color, file=stream), quiet=output.quiet, verbose=output.verbose)


def _status(items: list[Migrated], mode: str | None, fail_on: str | None, problems: list[str]) -> int:
    """The exit status (see ``cli.EXIT_STATUS``)."""
    if problems:
        return NOT_DONE
    results = [item.entry.result for item in items if item.entry.result is not None]
    if mode == "check" and any(result.changed for result in results):
        return GATE_FAILED
    if fail_on == "manual" and any(result.manual for result in results):
        return GATE_FAILED
    return 0


def _verify_status(verified: list[Verified], fail_on: str | None, problems: list[str]) -> int:
    """The exit status of ``--verify`` (see ``cli.EXIT_STATUS``)."""
    verdicts = {item.verification.verdict for item in verified}
    if problems or Verdict.INCOMPLETE in verdicts:
        return NOT_DONE
    if Verdict.DIVERGES in verdicts:
        return GATE_FAILED
    if fail_on == "manual" and any(item.verification.not_verified for item in verified):
        return GATE_FAILED
    return 0
