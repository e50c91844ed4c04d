"""``mint-migrate`` (also ``mint migrate``): migrate Mint v3 files to Mint v4.

Default is a dry run that prints a unified diff and the report. ``--write``
rewrites the files in place (atomically, in their own encoding and newlines,
through symbolic links, never over an edit made meanwhile; see ``writing`` and
``atomic``), ``--check`` only says whether anything would change, ``--stdout``
prints the migrated text of one file, ``--verify`` runs each v3 application and
its migration in the simulator and compares them (``verification``); the modes
exclude each other. Each
application is migrated on its own (``applications``): a rule that fails on one
is reported with its path and the rule, and the others are migrated and written.
"""

from __future__ import annotations

import difflib
import json
import sys
from dataclasses import dataclass, replace
from functools import partial
from pathlib import Path
from typing import NoReturn

import click
from rich.console import Console

from mintlang.cli.options import (
    HELP_OPTIONS,
    color_option,
    controller_option,
    drives_option,
    exit_zero_option,
    format_option,
    list_option,
    output_file_option,
    refuse_quiet_and_verbose,
    verbosity_options,
    version_option,
)
from mintlang.cli.settings import ProjectCommand, typed
from mintlang.cli.terminal import console, destination, refuse_overwriting
from mintlang.diagnostics import split_lines
from mintlang.migrate import leftovers, verifying
from mintlang.migrate.api import UnknownRule, rules, select
from mintlang.migrate.applications import Migrated, UsageError, read
from mintlang.migrate.citations import cite
from mintlang.migrate.report import render_text, report
from mintlang.migrate.verification import DEFAULT_UNTIL_MS, V3_CONTROLLERS, V3_DEFAULT, Verdict
from mintlang.migrate.verification.report import Verified
from mintlang.migrate.writing import write_changed

GATE_FAILED = 1
NOT_DONE = 2

EXIT_STATUS = """\b
Exit status:
  0  done: nothing left to rewrite (--check), everything written or
     printed, or every application verified equivalent (--verify; a
     timing difference X-GO-TIMING flagged counts as a manual item);
     manual items are reported and do not fail a run
  1  the gate failed: --check found something to rewrite, --verify found
     a divergence, or manual items are left and --fail-on manual was given
  2  something was not done: a usage error, a file that cannot be read
     or written, a file that changed since it was read (not written), a
     rule that failed on a file (that file is left as it was; the others
     are migrated and written), or a --verify comparison that could not
     cover the run (incomplete)"""


def _diff(item: Migrated, text: str) -> str:
    path = item.file.path
    lines = difflib.unified_diff(split_lines(item.file.text), split_lines(text), f"a/{path}", f"b/{path}", lineterm="")
    return "\n".join(lines)


def _list_rules(console: Console) -> None:
    for info in rules():
        kind = f"{info.rule_class.value}{' (optional)' if info.optional else ''}"
        console.print(f"[bold]{info.id:<14}[/bold] {kind:<21} {info.summary}", highlight=False)
        console.print(f"{'':<36} {cite(info.evidence)}", style="dim", highlight=False)


@click.command(
    name="migrate",
    cls=ProjectCommand,
    tool="mint-migrate",
    table="migrate",  # [tool.mint.migrate]: defaults for these options
    start=lambda params: next(iter(params["paths"]), Path()),
    context_settings=HELP_OPTIONS,
    epilog=EXIT_STATUS,
)
@click.argument("paths", nargs=-1, type=click.Path(path_type=Path))
@click.option("--write", is_flag=True, help="Rewrite the files in place.")
@click.option("--check", is_flag=True, help="Exit 1 when anything would be rewritten; write nothing.")
@click.option("--stdout", "to_stdout", is_flag=True, help="Print the migrated text of one file.")
@click.option(
    "--config",
    "config",
    type=click.Path(path_type=Path),
    help="Configuration file migrated together with the program (its variables are visible there).",
)
@controller_option("The Mint v4 controller to migrate to.")
@format_option(["text", "json"])
@output_file_option("Write the diff and the report to this file instead of standard output.")
@click.option("--fail-on", "fail_on", type=click.Choice(["manual"]), help="Exit 1 when manual items are left.")
@exit_zero_option("Exit with 0 when the gate fails (--check, --verify, --fail-on); 2 still means not done.")
@list_option("--only", metavar="RULES", help="Run only these rules (comma-separated or repeated).")
@list_option("--skip", metavar="RULES", help="Do not run these rules (comma-separated or repeated).")
@list_option("--with", "opt_in", metavar="RULES", help="Also run these optional rules (comma-separated or repeated).")
@click.option("--list-rules", is_flag=True, help="List the rules and exit.")
@verbosity_options(
    quiet="Leave out the table of files, the rule counts and the totals.",
    verbose="Also list every change: its rule and its line in the migrated and the original file.",
)
@color_option()
@version_option("mint-migrate")
@click.option(
    "--verify",
    is_flag=True,
    help="Run each v3 application and its migration in the simulator and compare them; write nothing.",
)
@click.option(
    "--scenario",
    "scenario_paths",
    multiple=True,
    type=click.Path(path_type=Path),
    help="With --verify: a mint-run scenario file (TOML) giving both runs the same stimulus (repeatable).",
)
@click.option(
    "--until-ms",
    type=click.IntRange(min=1),
    help=f"With --verify: compare at most this many simulated ms.  [default: {DEFAULT_UNTIL_MS}]",
)
@click.option(
    "--v3-controller",
    type=click.Choice(list(V3_CONTROLLERS)),
    help=f"With --verify: the Mint v3 controller the originals run on.  [default: {V3_DEFAULT}]",
)
@drives_option("With --verify: start both runs with every drive enabled (as mint-run --drives enabled).")
def migrate(  # noqa: PLR0917 - click passes every option as an argument
    paths: tuple[Path, ...],
    write: bool,
    check: bool,
    to_stdout: bool,
    config: Path | None,
    controller: str,
    output_format: str,
    output_file: Path | None,
    fail_on: str | None,
    exit_zero: bool,
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
    """Migrate Mint v3 programs (.mnt) and configuration files (.cfg) to Mint v4."""
    refuse_quiet_and_verbose(quiet, verbose)
    if list_rules:
        _list_rules(console(color))
        return
    try:
        mode = _mode(write=write, check=check, to_stdout=to_stdout, verify=verify)
        options = verifying.Options(scenario_paths, until_ms, v3_controller, drives)
        context = click.get_current_context()
        settings = options.settings(controller) if mode == "verify" else options.refuse(partial(typed, context))
        select(only or None, skip, opt_in)
        applications = read(paths, config)
        if mode == "stdout" and sum(len(application.files()) for application in applications) > 1:
            raise UsageError("--stdout prints one file: name one program or one configuration file")
    except (UsageError, UnknownRule) as error:
        _fail(str(error))
    sources = [file.path for application in applications for file, _ in application.files()]
    refuse_overwriting(output_file, sources, _fail)
    migrated = [application.migrate(controller, only or None, skip, opt_in) for application in applications]
    items = [item for application in migrated for item in application]
    problems = [f"{item.entry.path}: {item.entry.failure}; left as it was" for item in items if item.entry.failure]
    _tidy(items, mode)
    if settings is not None:
        verified, failed = verifying.verify_all(migrated, settings)
        with destination(output_file, _fail) as stream:
            verifying.output(verified, output_format, console(color, file=stream), quiet=quiet)
        for problem in [*problems, *failed]:
            click.echo(f"mint-migrate: {problem}", err=True)
        status = _verify_status(verified, fail_on, [*problems, *failed])
        sys.exit(0 if status == GATE_FAILED and exit_zero else status)
    if mode == "write":
        written = write_changed(migrated)
        problems += written.problems
        items = [_unwritten(item) if item.file.path in written.unwritten else item for item in items]
    _output(items, mode, output_format, controller, Output(output_file, quiet, verbose, color))
    for problem in problems:
        click.echo(f"mint-migrate: {problem}", err=True)
    status = _status(items, mode, fail_on, problems)
    sys.exit(0 if status == GATE_FAILED and exit_zero else status)


def _unwritten(item: Migrated) -> Migrated:
    """``item`` reported as a changed file ``--write`` left as it was."""
    return replace(item, entry=replace(item.entry, written=False))


def _fail(message: str) -> NoReturn:
    click.echo(f"mint-migrate: {message}", err=True)
    sys.exit(NOT_DONE)


def _mode(*, write: bool, check: bool, to_stdout: bool, verify: bool) -> str | None:
    """The one mode asked for: ``--check --write`` must not write, so two are a usage error."""
    modes = (("write", write), ("check", check), ("stdout", to_stdout), ("verify", verify))
    given = [name for name, on in modes if on]
    if len(given) > 1:
        raise UsageError(f"{', '.join('--' + name for name in given)}: choose one of these modes")
    return given[0] if given else None


def _tidy(items: list[Migrated], mode: str | None) -> None:
    """Temporary files an interrupted ``--write`` left beside these files: removed by
    ``--write`` (before anything is written), named by the modes that write nothing."""
    found = leftovers.find(item.file.path.resolve().parent for item in items)
    for line in leftovers.remove(found) if mode == "write" else leftovers.named(found):
        click.echo(f"mint-migrate: {line}", err=True)


@dataclass(frozen=True, slots=True)
class Output:
    """Where the diff and the report go (standard output, or ``--output-file``), and how they look."""

    path: Path | None
    quiet: bool
    verbose: bool
    color: str


def _output(items: list[Migrated], mode: str | None, output_format: str, controller: str, output: Output) -> None:
    data = report((item.entry for item in items), controller)
    if mode == "stdout":
        result = items[0].entry.result
        if result is not None:
            sys.stdout.buffer.write(items[0].file.encode(result.text))
            sys.stdout.buffer.flush()
    with destination(output.path, _fail, stderr=mode == "stdout") as stream:
        if mode is None and output_format == "text":
            for item in items:
                if item.entry.result is not None and item.entry.result.changed:
                    click.echo(_diff(item, item.entry.result.text), file=stream)
        if output_format == "json":
            click.echo(json.dumps(data, indent=2, ensure_ascii=False), file=stream)
        else:
            render_text(data, console(output.color, file=stream), quiet=output.quiet, verbose=output.verbose)


def _status(items: list[Migrated], mode: str | None, fail_on: str | None, problems: list[str]) -> int:
    """The exit status (see ``EXIT_STATUS``)."""
    if problems:
        return NOT_DONE
    results = [item.entry.result for item in items if item.entry.result is not None]
    if mode == "check" and any(result.changed for result in results):
        return GATE_FAILED
    if fail_on == "manual" and any(result.manual for result in results):
        return GATE_FAILED
    return 0


def _verify_status(verified: list[Verified], fail_on: str | None, problems: list[str]) -> int:
    """The exit status of ``--verify`` (see ``EXIT_STATUS``)."""
    verdicts = {item.verification.verdict for item in verified}
    if problems or Verdict.INCOMPLETE in verdicts:
        return NOT_DONE
    if Verdict.DIVERGES in verdicts:
        return GATE_FAILED
    if fail_on == "manual" and any(item.verification.not_verified for item in verified):
        return GATE_FAILED
    return 0


def main() -> None:
    """Entry point of the ``mint-migrate`` script."""
    migrate()
