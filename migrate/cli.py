"""``mint-migrate`` (also ``mint migrate``): migrate Mint v3 files to Mint v4.

Default is a dry run that prints a unified diff and the report. ``--write``
rewrites the files in place (atomically, in their own encoding and newlines,
through symbolic links; see ``atomic``), ``--check`` only says whether anything
would change, ``--stdout`` prints the migrated text of one file; the modes
exclude each other. Every file to write is checked before the first is written.
Exit status: 0 when there is nothing to do or all was written, 1 when changes
are pending (``--check``) or manual items are left, 2 for a usage or I/O problem
(one line, never a traceback).
"""

from __future__ import annotations

import difflib
import json
import sys
from dataclasses import dataclass
from pathlib import Path

import click
from rich.console import Console

from mintlang.cli.files import collect, is_configuration, program_as_own_configuration
from mintlang.cli.options import controller_option
from mintlang.diagnostics import split_lines
from mintlang.migrate.api import UnknownRule, rules, select
from mintlang.migrate.api import migrate as migrate_text
from mintlang.migrate.atomic import Unwritable, target
from mintlang.migrate.atomic import write as write_file
from mintlang.migrate.model import MigrationResult
from mintlang.migrate.report import FileEntry, render_text, report
from mintlang.source import SourceFile, read_source

_PENDING = 1
_USAGE_ERROR = 2


class _Usage(Exception):
    """A problem with the command line or a file: reported in one line, exit status 2."""


@dataclass(frozen=True)
class _Job:
    """One application to migrate: a program, its configuration file, or both."""

    program: SourceFile | None
    configuration: SourceFile | None

    def run(
        self, controller: str, only: tuple[str, ...] | None, skip: tuple[str, ...], opt_in: tuple[str, ...]
    ) -> list[tuple[SourceFile, FileEntry]]:
        config = self.configuration.text if self.configuration is not None else None
        program = self.program.text if self.program else ""
        result = migrate_text(program, config=config, controller=controller, only=only, skip=skip, opt_in=opt_in)
        pairs = []
        if self.configuration is not None and result.configuration is not None:
            pairs.append((self.configuration, _entry(self.configuration, "configuration", result.configuration)))
        if self.program is not None:
            pairs.append((self.program, _entry(self.program, "program", result)))
        return pairs


def _entry(file: SourceFile, role: str, result: MigrationResult) -> FileEntry:
    return FileEntry(str(file.path), role, result)


def _read(path: Path) -> SourceFile:
    try:
        file = read_source(path)
    except OSError as error:
        raise _Usage(f"cannot read {path}: {error.strerror or error}") from None
    binary = file.binary()
    if binary is not None:
        raise _Usage(f"{binary}: nothing migrated")
    return file


def _jobs(paths: tuple[Path, ...], config: Path | None) -> list[_Job]:
    try:
        found = collect(paths)
    except FileNotFoundError as error:
        raise _Usage(f"no such file or directory: {error.filename or error.args[0]}") from None
    except OSError as error:  # a link loop, a path under a file, a folder that cannot be read
        raise _Usage(f"cannot read {error.filename}: {error.strerror or error}") from None
    if config is not None:
        if len(found) > 1 or any(is_configuration(path) for path in found):
            raise _Usage("--config pairs one configuration file with one program file")
        itself = program_as_own_configuration(found, config)
        if itself is not None:  # read in both roles; with --write the second write would undo the first
            raise _Usage(f"--config {config} is the program {itself} itself: name the configuration file")
        return [_Job(_read(found[0]) if found else None, _read(config))]
    if not found:
        raise _Usage("no .mnt or .cfg files to migrate")
    return [_Job(None, _read(p)) if is_configuration(p) else _Job(_read(p), None) for p in found]


def _diff(file: SourceFile, text: str) -> str:
    lines = difflib.unified_diff(
        split_lines(file.text), split_lines(text), f"a/{file.path}", f"b/{file.path}", lineterm=""
    )
    return "\n".join(lines)


def _list_rules(console: Console) -> None:
    for info in rules():
        kind = f"{info.rule_class.value}{' (optional)' if info.optional else ''}"
        console.print(f"[bold]{info.id:<14}[/bold] {kind:<21} {info.summary}", highlight=False)
        console.print(f"{'':<36} {info.evidence}", style="dim", highlight=False)


@click.command(name="migrate", context_settings={"help_option_names": ["-h", "--help"]})
@click.argument("paths", nargs=-1, type=click.Path(path_type=Path))
@click.option("--write", is_flag=True, help="Rewrite the files in place.")
@click.option("--check", is_flag=True, help="Exit 1 when anything would change; write nothing.")
@click.option("--stdout", "to_stdout", is_flag=True, help="Print the migrated text of one file.")
@click.option(
    "--config",
    "config",
    type=click.Path(path_type=Path),
    help="Configuration file migrated together with the program (its variables are visible there).",
)
@controller_option("The Mint v4 controller to migrate to.")
@click.option("--format", "output_format", type=click.Choice(["text", "json"]), default="text", show_default=True)
@click.option("--only", multiple=True, metavar="RULE", help="Run only this rule (repeatable).")
@click.option("--skip", multiple=True, metavar="RULE", help="Do not run this rule (repeatable).")
@click.option("--with", "opt_in", multiple=True, metavar="RULE", help="Also run this optional rule (repeatable).")
@click.option("--list-rules", is_flag=True, help="List the rules and exit.")
def migrate(  # noqa: PLR0917 - click passes every option as an argument
    paths: tuple[Path, ...],
    write: bool,
    check: bool,
    to_stdout: bool,
    config: Path | None,
    controller: str,
    output_format: str,
    only: tuple[str, ...],
    skip: tuple[str, ...],
    opt_in: tuple[str, ...],
    list_rules: bool,
) -> None:
    """Migrate Mint v3 programs (.mnt) and configuration files (.cfg) to Mint v4."""
    out = Console(highlight=False, soft_wrap=True)
    if list_rules:
        _list_rules(out)
        return
    try:
        mode = _mode(write=write, check=check, to_stdout=to_stdout)
        select(only or None, skip, opt_in)
        jobs = _jobs(paths, config)
        if mode == "stdout" and sum((job.program is not None) + (job.configuration is not None) for job in jobs) > 1:
            raise _Usage("--stdout prints one file: name one program or one configuration file")
        migrated = [pair for job in jobs for pair in job.run(controller, only or None, skip, opt_in)]
        changed = [(file, entry) for file, entry in migrated if entry.result.changed]
        writes = _targets(changed) if mode == "write" else []
        _output(migrated, mode, output_format, controller)
        _write(writes)
    except (_Usage, UnknownRule, Unwritable) as error:
        click.echo(f"mint-migrate: {error}", err=True)
        sys.exit(_USAGE_ERROR)
    manual = any(entry.result.manual for _, entry in migrated)
    pending = mode == "check" and bool(changed)
    sys.exit(_PENDING if manual or pending else 0)


def _mode(*, write: bool, check: bool, to_stdout: bool) -> str | None:
    """The one mode asked for: ``--check --write`` must not write, so two are a usage error."""
    given = [name for name, on in (("write", write), ("check", check), ("stdout", to_stdout)) if on]
    if len(given) > 1:
        raise _Usage(f"{', '.join('--' + name for name in given)}: choose one of these modes")
    return given[0] if given else None


def _targets(changed: list[tuple[SourceFile, FileEntry]]) -> list[tuple[Path, SourceFile, FileEntry]]:
    """Each changed file with the real file to write, all checked before the first is written."""
    try:
        return [(target(file.path), file, entry) for file, entry in changed]
    except Unwritable as error:
        raise Unwritable(f"{error}; nothing was written") from None


def _write(writes: list[tuple[Path, SourceFile, FileEntry]]) -> None:
    """Write each changed file to its real file, stopping at the first that fails: the message
    names it and says which files were already written and which were left as they were."""
    for done, (real, file, entry) in enumerate(writes):
        try:
            write_file(real, file.encode(entry.result.text))
        except OSError as error:
            written = [str(other.path) for _, other, _ in writes[:done]]
            left = [str(other.path) for _, other, _ in writes[done + 1 :]]
            message = f"cannot write {real}: {error.strerror or error}"
            message += f"; written: {', '.join(written)}" if written else "; nothing was written"
            if left:
                message += f"; not written: {', '.join(left)}"
            raise Unwritable(message) from None


def _output(
    migrated: list[tuple[SourceFile, FileEntry]], mode: str | None, output_format: str, controller: str
) -> None:
    data = report((entry for _, entry in migrated), controller)
    to_stderr = mode == "stdout"
    console = Console(highlight=False, soft_wrap=True, stderr=to_stderr)
    if mode == "stdout":
        file, entry = migrated[0]
        sys.stdout.buffer.write(file.encode(entry.result.text))
        sys.stdout.buffer.flush()
    elif mode is None and output_format == "text":
        for file, entry in migrated:
            if entry.result.changed:
                click.echo(_diff(file, entry.result.text))
    if output_format == "json":
        click.echo(json.dumps(data, indent=2, ensure_ascii=False), err=to_stderr)
    else:
        render_text(data, console)


def main() -> None:
    """Entry point of the ``mint-migrate`` script."""
    migrate()
