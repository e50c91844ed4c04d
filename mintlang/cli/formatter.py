"""``mint format``: the house style (``mintlang.formatting``) written into the files, as ``ruff format`` does.

The files are found as ``mint check`` finds them (its exclusions and settings files), configuration files
included; the settings file's ``[format]`` table gives the options' defaults (``indent-width = 4``). Each
file is written atomically and only if it still holds what was read (``cli.fixing.apply``).
``--check`` and ``--diff`` write nothing and exit 1 when a file would change, for a CI gate or a hook.
A file read as Mint v4 by default that shows MintMT's forms is left as it is: v4 would take its ``'`` comments
for code and write their words in upper case. So is a file with a syntax error, named at its place, as ruff
names a file it cannot parse.
"""

from __future__ import annotations

import sys
from dataclasses import replace
from pathlib import Path
from typing import NoReturn

import click

from mintlang.cli.checking import FileFixed
from mintlang.cli.diffs import unified, write_diff
from mintlang.cli.files import CONFIGURATION_SUFFIXES, PROGRAM_SUFFIXES, cannot_read, find, is_configuration
from mintlang.cli.fixing import apply
from mintlang.cli.options import (
    HELP_OPTIONS,
    exclude_options,
    refuse_quiet_and_verbose,
    verbosity_options,
    version_option,
)
from mintlang.cli.settings import ProjectCommand, exclusions, settings_failed
from mintlang.detection import first_mintmt_form
from mintlang.dialect import Dialect
from mintlang.fixes import Fixed
from mintlang.formatting import INDENT_STYLES, INDENT_WIDTH, Unparsable, format_text, indent_unit
from mintlang.settings import FileSettings, Given, Overrides, SettingsError, settings_for
from mintlang.source import SourceFile, read_source, read_stdin

_CHANGES = 1
_NOT_DONE = 2
_STDIN = Path("-")

EXIT_STATUS = """\b
Exit status:
  0  the files are formatted (or were written so)
  1  with --check or --diff: a file would be reformatted
  2  a usage error, or a file that could not be read or written"""


@click.command(
    "format",
    cls=ProjectCommand,
    tool="mint format",
    table="format",  # [tool.mint.format]: indent-width, indent-style, ...
    start=lambda params: _settings_start(params["paths"], params["stdin_filename"]),
    context_settings=HELP_OPTIONS,
    epilog=EXIT_STATUS,
)
@click.argument("paths", nargs=-1, type=click.Path(path_type=Path))
@version_option("mint format")
@click.option("--check", is_flag=True, help="Write nothing: name the files that would be reformatted (exit 1).")
@click.option("--diff", is_flag=True, help="Show the changes as a unified diff instead of writing them (exit 1).")
@click.option("--dialect", type=click.Choice([d.value for d in Dialect]), help="[default: the settings', or v4]")
@click.option(
    "--indent-width", type=click.IntRange(1, 16), default=INDENT_WIDTH, show_default=True, help="Spaces a level."
)
@click.option("--indent-style", type=click.Choice(INDENT_STYLES), default="space", show_default=True)
@click.option("--stdin-filename", help="The name under which the text read from standard input (the path -) is read.")
@exclude_options()
@verbosity_options(quiet="Say nothing but errors.", verbose="Name every file reformatted.")
def format_command(
    paths: tuple[Path, ...],
    check: bool,
    diff: bool,
    dialect: str | None,
    indent_width: int,
    indent_style: str,
    stdin_filename: str | None,
    exclude: tuple[str, ...] | None,
    extend_exclude: tuple[str, ...] | None,
    force_exclude: bool | None,
    quiet: bool,
    verbose: bool,
) -> None:
    """Format Mint programs and configuration files: upper-case keywords, blocks indented, labels at the margin.

    PATHS are files and directories (the current directory if none is given); directories are searched for
    .mnt and .cfg files as mint check searches them; - formats standard input to standard output, as an
    editor's formatter hook pipes a buffer. Only whitespace and letter case change (MintMT keeps its words'
    case).
    """
    refuse_quiet_and_verbose(quiet, verbose)
    layer = exclusions(exclude, extend_exclude, force_exclude)
    if dialect is not None:
        layer = replace(layer, dialect=Given(Dialect(dialect), "--dialect"))
    level = indent_unit(indent_style, indent_width)
    if _STDIN in paths:
        if len(paths) > 1:
            raise click.UsageError("- formats standard input alone: give no other path")
        _format_stdin(stdin_filename, layer, level, check=check, diff=diff)
    if stdin_filename is not None:
        raise click.UsageError("--stdin-filename names the text read from standard input: give - as the path")
    found = find(paths or (Path(),), PROGRAM_SUFFIXES | CONFIGURATION_SUFFIXES, overrides=layer)
    problems = [cannot_read(error) for error in found.unreadable]
    changes: list[FileFixed] = []
    unchanged = 0
    for path in found.files:
        try:
            source = read_source(path)
        except OSError as error:
            problems.append(cannot_read(error))
            continue
        text, problem = _formatted(source, layer, level)
        if problem is not None:
            problems.append(problem)
        elif text == source.text:
            unchanged += 1
        else:
            changes.append(FileFixed(source, Fixed(text, (), (), converged=True)))
    if check or diff:
        _report_only(changes, unchanged, diff=diff, quiet=quiet)
        written = changes
    else:
        outcome = apply(changes, diff=None)
        problems += outcome.problems
        written = [change for change in changes if change.original.path not in outcome.unwritten]
        if verbose:
            click.echo("".join(f"reformatted {change.original.path}\n" for change in written), nl=False)
        if not quiet:
            click.echo(f"{_files(len(written))} reformatted, {_files(unchanged)} left unchanged")
    for problem in problems:
        click.echo(f"mint format: {problem}", err=True)
    sys.exit(_NOT_DONE if problems else _CHANGES if (check or diff) and written else 0)


def _settings_start(paths: tuple[Path, ...], stdin_filename: str | None) -> Path:
    """Where the settings file is looked for: above the first path, or standard input's name."""
    if _STDIN in paths:
        return Path(stdin_filename or "-")
    return next(iter(paths), Path())


def _format_stdin(name: str | None, layer: Overrides, level: str, *, check: bool, diff: bool) -> NoReturn:
    """Standard input formatted to standard output; with ``check`` or ``diff`` only what would change."""
    source = read_stdin(name)
    text, problem = _formatted(source, layer, level)
    if problem is not None:
        click.echo(f"mint format: {problem}", err=True)
        sys.exit(_NOT_DONE)
    changed = text != source.text
    if diff:
        write_diff(sys.stdout, unified(source.text, text, str(source.path), str(source.path)), source.encoding)
    elif check:
        click.echo(f"Would reformat: {source.path}" if changed else "", nl=changed)
    else:
        sys.stdout.buffer.write(source.encode(text))
        sys.stdout.buffer.flush()
    sys.exit(_CHANGES if changed and (check or diff) else 0)


def _formatted(source: SourceFile, layer: Overrides, level: str) -> tuple[str, str | None]:
    """``source``'s text in the house style, read as its settings say, and None; or its own text and why it is left
    as it is. A settings file that cannot be used ends the command."""
    try:
        settings = settings_for(source.path, layer)
    except SettingsError as error:
        settings_failed("mint format", error)
    if (problem := _not_formatted(source, settings.dialect)) is not None:
        return source.text, problem
    configuration = is_configuration(source.path)
    seen = None if configuration else _configuration_text(source.path, settings)
    try:
        return format_text(source.text, level, settings.dialect.value, configuration=configuration, seen=seen), None
    except Unparsable as error:
        return source.text, f"{source.path}:{error}: not formatted"


def _configuration_text(program: Path, settings: FileSettings) -> str | None:
    """The text of the configuration file ``program`` sees, as ``mint check`` pairs them (its macros are the
    program's); None when it has none, or one that cannot be read (``mint check`` says why)."""
    _, other = settings.partner(program)
    if other is None:
        return None
    try:
        configuration = read_source(other)
    except OSError:
        return None
    return configuration.text if configuration.binary() is None else None


def _not_formatted(source: SourceFile, dialect: Given[Dialect]) -> str | None:
    """Why ``source`` is left as it is, or None: it is not text, or it shows MintMT's forms but no one chose its
    dialect (v4 would upper-case the words of its ``'`` comments, which it reads as code)."""
    if (binary := source.binary()) is not None:
        return f"{binary}: not formatted"
    if dialect.chosen or dialect.value is not Dialect.V4 or (form := first_mintmt_form(source.text)) is None:
        return None
    seen = f"{form.what} on line {form.line}"
    return f"{source.path}: looks like MintMT ({seen}) but would be read as Mint v4: not formatted (--dialect mintmt)"


def _report_only(changes: list[FileFixed], unchanged: int, *, diff: bool, quiet: bool) -> None:
    """``--diff``'s diffs, or ``--check``'s names, and what would be done."""
    if diff:
        apply(changes, diff=sys.stdout)
    elif not quiet:
        click.echo("".join(f"Would reformat: {change.original.path}\n" for change in changes), nl=False)
    if not quiet:
        click.echo(f"{_files(len(changes))} would be reformatted, {_files(unchanged)} already formatted", err=diff)


def _files(count: int) -> str:
    return f"{count} file{'s' if count != 1 else ''}"
