"""What ``mint test`` does once its command line is read (``cli`` declares the command line).

Kept apart so that ``mint test --help`` (and ``mint --help``, which lists it) loads neither the simulator nor rich.
"""

from __future__ import annotations

import shlex
import sys
import time
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, NoReturn

import click

from mintlang.cli.options import refuse_quiet_and_verbose
from mintlang.cli.parallel import all_cores, map_in_order
from mintlang.cli.settings import exclusions, without_configuration
from mintlang.cli.terminal import console, destination, reader_may_leave, refuse_overwriting, write_in_pieces
from mintlang.dialect import Dialect
from mintlang.runtime.outputs import OutputProblem, check_report
from mintlang.runtime.testing import reports
from mintlang.runtime.testing.coverage import lcov as tracefile
from mintlang.runtime.testing.coverage import merge
from mintlang.runtime.testing.discovery import discover
from mintlang.runtime.testing.running import Options, TestResult, Verdict, run_case

if TYPE_CHECKING:
    from rich.console import Console

    from mintlang.runtime.testing.selection import Selector

PASSED, FAILED, USAGE, NO_TESTS = 0, 1, 2, 5


@reader_may_leave()
def execute(  # noqa: PLR0917 - click passes every option as an argument
    paths: tuple[Path, ...],
    controller: str | None,
    dialect: str | None,
    until_ms: int | None,
    max_wall_s: float,
    drives: str | None,
    coverage: bool,
    lcov: Path | None,
    no_config: bool,
    exclude: tuple[str, ...] | None,
    extend_exclude: tuple[str, ...] | None,
    force_exclude: bool | None,
    jobs: int | None,
    keyword: str | None,
    collect_only: bool,
    output_format: str,
    output_file: Path | None,
    exit_zero: bool,
    color: str,
    quiet: bool,
    verbose: bool,
) -> None:
    """Run the tests as ``test`` was asked to (its docstring says which programs are tests)."""
    refuse_quiet_and_verbose(quiet, verbose)
    if collect_only and output_format == "junit":
        raise click.UsageError("--collect-only lists the tests as text or json, not junit")
    if lcov is not None and not coverage:  # else the run ends with no tracefile and no word of why
        raise click.UsageError(f"--lcov {lcov} names the tracefile --coverage writes: add --coverage")
    tracefile_path = lcov or Path("lcov.info")
    selected = _selector(keyword)
    layer = exclusions(exclude, extend_exclude, force_exclude)
    layer = without_configuration(layer) if no_config else layer
    cases, unreadable = discover(paths or (Path(),), layer)
    errors = console(color, stderr=True)
    for problem in unreadable:
        errors.print(f"mint test: {problem.message}", markup=False)
    if not cases:
        errors.print("mint test: no tests found (programs with REM @expect lines or a .scenario.toml beside them)")
        sys.exit(USAGE if unreadable else NO_TESTS)
    found = len(cases)
    cases = [case for case in cases if selected(case.name)]
    if not cases:
        none = f"mint test: -k {shlex.quote(keyword or '')} selected none of the {found} tests found"
        errors.print(none, markup=False)
        sys.exit(USAGE if unreadable else NO_TESTS)
    if collect_only:
        with destination(output_file, _fail) as stream:
            write_in_pieces(stream, reports.collected(cases, as_json=output_format == "json"))
        sys.exit(USAGE if unreadable else PASSED)
    enabled = drives == "enabled"
    inputs = [path for case in cases for path in (case.program, case.scenario) if path is not None]
    for output in (output_file, tracefile_path if coverage else None):
        refuse_overwriting(output, inputs, _fail)
        _writable(output)
    options = Options(controller, Dialect(dialect) if dialect else None, until_ms, max_wall_s, enabled, coverage, layer)
    began = time.perf_counter()
    results = map_in_order(
        partial(run_case, options=options),
        cases,
        workers=jobs or all_cores(),
        progress=None if quiet else errors,
        description="testing",
    )
    seconds = time.perf_counter() - began
    with destination(output_file, _fail) as stream:
        if output_format == "junit":
            write_in_pieces(stream, reports.junit(results, seconds))
        elif output_format == "json":
            write_in_pieces(stream, reports.as_json(results, seconds))
        else:
            shown = console(color if output_file is None else "never", file=stream)
            reports.text(results, seconds, shown, deselected=found - len(cases), quiet=quiet, verbose=verbose)
    if coverage:
        _coverage(results, tracefile_path, None if quiet else console(color, stderr=output_format != "text"))
    if not quiet:
        for note in reports.warnings(results):
            errors.print(f"warning: {note}", style="yellow", markup=False, highlight=False)
        click.echo("".join(f"{result.hint}\n" for result in results if result.hint is not None), err=True, nl=False)
    if unreadable:
        sys.exit(USAGE)
    passed = all(result.verdict is Verdict.PASSED for result in results)
    sys.exit(PASSED if passed or exit_zero else FAILED)


def _selector(keyword: str | None) -> Selector:
    """The tests ``-k`` selects, every one without it; an expression that cannot be read is a usage error."""
    if keyword is None:
        return lambda _path: True
    from mintlang.runtime.testing.selection import KeywordError, selector  # noqa: PLC0415 - lark, for a -k only

    try:
        return selector(keyword)
    except KeywordError as error:
        raise click.UsageError(f"-k {shlex.quote(keyword)}: {error}") from None


def _coverage(results: list[TestResult], lcov: Path, table: Console | None) -> None:
    """The table on ``table`` (beside a text report, else on standard error; none when quiet) and the
    lcov tracefile."""
    files = merge(result.coverage for result in results)
    if table is not None:
        reports.coverage_table(files, table)
    try:
        lcov.write_text(tracefile(files), encoding="utf-8")
    except OSError as error:
        _fail(f"cannot write {lcov}: {error.strerror or error}")


def _writable(output: Path | None) -> None:
    """Refuse an output that cannot be written before any test runs: found after the run, its results were lost."""
    if output is not None:
        try:
            check_report(output, {})
        except OutputProblem as problem:
            _fail(str(problem))


def _fail(message: str) -> NoReturn:
    click.echo(f"mint test: {message}", err=True)
    sys.exit(USAGE)
