"""``mint check``: the static analyser on the command line.

Exit status: 0 when no diagnostic of error severity was found, 1 when one was,
2 for a usage or I/O problem (reported in one line, never as a traceback).
"""

from __future__ import annotations

import sys
from collections import Counter
from pathlib import Path
from typing import NoReturn

import click
from rich.console import Console

from mintlang import check_application
from mintlang.cli.files import collect, is_configuration, program_as_own_configuration, same_file
from mintlang.cli.options import controller_option
from mintlang.cli.report import FileReport, as_github, as_json, as_sarif, render_text
from mintlang.codes import known_codes
from mintlang.diagnostics import Diagnostic, Severity
from mintlang.dialect import Dialect
from mintlang.source import SourceFile, read_source

_USAGE_ERROR = 2
_USE_FINDINGS = frozenset({"W103", "W105"})  # unused variable, macro: a use in any program counts


def _codes(value: str | None, option: str) -> tuple[str, ...] | None:
    """The codes or prefixes of ``--select``/``--ignore``; a typo would silently hide findings, so none passes."""
    if value is None:
        return None
    codes = tuple(code.strip().upper() for code in value.split(",") if code.strip())
    if not codes:
        raise click.BadParameter("give at least one code or prefix (E2, W103 ...)", param_hint=option)
    known = known_codes()
    for code in codes:
        if not any(name.startswith(code) for name in known):
            raise click.BadParameter(f"'{code}' is no code and begins none (E2003, W1, I201 ...)", param_hint=option)
    return codes


def _fail(message: str) -> NoReturn:
    click.echo(f"mint check: {message}", err=True)
    sys.exit(_USAGE_ERROR)


@click.command()
@click.argument("paths", nargs=-1, required=True, type=click.Path(path_type=Path))
@click.option("--dialect", type=click.Choice([d.value for d in Dialect]), default="v4", show_default=True)
@controller_option("The controller the programs run on.")
@click.option(
    "--config",
    "config_path",
    type=click.Path(path_type=Path),
    help="Configuration file whose variables and macros the programs see.",
)
@click.option(
    "--format",
    "output_format",
    type=click.Choice(["text", "json", "sarif", "github"]),
    default="text",
    show_default=True,
)
@click.option(
    "--select",
    help="Only these codes or code prefixes, comma-separated (E2,W103). Default: E,W; the hints need it (--select I).",
)
@click.option("--ignore", help="Leave out these codes or code prefixes, comma-separated.")
def check(
    paths: tuple[Path, ...],
    dialect: str,
    controller: str,
    config_path: Path | None,
    output_format: str,
    select: str | None,
    ignore: str | None,
) -> None:
    """Check Mint programs (.mnt; directories are searched) for the controller's errors and more."""
    options: dict[str, object] = {
        "dialect": dialect,
        "controller": controller,
        "select": _codes(select, "--select"),
        "ignore": _codes(ignore, "--ignore") or (),
    }
    try:
        files = collect(paths)
        configuration = read_source(config_path) if config_path is not None else None
    except FileNotFoundError as missing:
        _fail(f"no such file or directory: {missing.filename or missing.args[0]}")
    except OSError as error:
        _fail(f"cannot read {error.filename}: {error.strerror}")
    if configuration is not None and (binary := configuration.binary()) is not None:
        _fail(f"{binary}: not checked")
    if not files:
        _fail("no .mnt files found in " + ", ".join(str(p) for p in paths))
    itself = program_as_own_configuration(files, config_path) if config_path is not None else None
    if itself is not None:
        _fail(f"--config {config_path} is the program {itself} itself: name the configuration file")

    reports: list[FileReport] = []
    seen_by_programs: list[tuple[Diagnostic, ...]] = []  # the configuration's findings with each program
    for path in files:
        if configuration is not None and is_configuration(path) and same_file(path, configuration.path):
            continue  # named twice, as --config and as a path: checked once, with the programs
        try:
            source = read_source(path)
        except OSError as error:
            _fail(f"cannot read {path}: {error.strerror}")
        binary = source.binary()
        if binary is not None:
            _fail(f"{binary}: not checked")
        if is_configuration(path):
            reports.append(_configuration_report(source, options))
        else:
            config_text = configuration.text if configuration is not None else None
            analysis = check_application(source.text, config=config_text, **options)  # type: ignore[arg-type]
            reports.append(FileReport(str(path), source.text, analysis.program))
            seen_by_programs.append(analysis.configuration)
    if configuration is not None:
        if seen_by_programs:
            diagnostics = _configuration_with_programs(seen_by_programs)
            reports.insert(0, FileReport(str(configuration.path), configuration.text, diagnostics))
        else:
            reports.insert(0, _configuration_report(configuration, options))

    if output_format == "json":
        click.echo(as_json(reports))
    elif output_format == "sarif":
        click.echo(as_sarif(reports))
    elif output_format == "github":
        output = as_github(reports)
        if output:
            click.echo(output)
    else:
        render_text(reports, Console(highlight=False, soft_wrap=True))
    failed = any(d.severity is Severity.ERROR for report in reports for d in report.diagnostics)
    sys.exit(1 if failed else 0)


def _configuration_with_programs(seen_by_programs: list[tuple[Diagnostic, ...]]) -> tuple[Diagnostic, ...]:
    """The configuration's findings, each once; a name is unused only if no program uses it."""
    counts: Counter[Diagnostic] = Counter(d for diagnostics in seen_by_programs for d in dict.fromkeys(diagnostics))
    kept = [d for d, count in counts.items() if d.code not in _USE_FINDINGS or count == len(seen_by_programs)]
    return tuple(sorted(kept, key=lambda d: (d.span.start, d.span.end, d.code)))


def _configuration_report(source: SourceFile, options: dict[str, object]) -> FileReport:
    """A configuration file checked on its own (with an empty program)."""
    analysis = check_application("", config=source.text, **options)  # type: ignore[arg-type]
    return FileReport(str(source.path), source.text, analysis.configuration)
