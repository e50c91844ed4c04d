"""``mint test``: run every Mint program under the given paths that carries its own checks.

Exit status: 0 when every test passed, 1 when one failed or could not be
judged, 2 for a usage problem or a path that cannot be read (the other tests
still run), 5 when no test was found (as pytest does).
"""

from __future__ import annotations

import sys
import time
from functools import partial
from pathlib import Path
from typing import NoReturn

import click

from mintlang.cli.options import (
    HELP_OPTIONS,
    color_option,
    drives_option,
    exit_zero_option,
    format_option,
    output_file_option,
    version_option,
)
from mintlang.cli.parallel import all_cores, map_in_order
from mintlang.cli.terminal import console, destination, refuse_overwriting
from mintlang.dialect import Dialect
from mintlang.runtime.dialects import SIMULATED
from mintlang.runtime.testing import reports
from mintlang.runtime.testing.coverage import lcov as tracefile
from mintlang.runtime.testing.coverage import merge
from mintlang.runtime.testing.discovery import discover
from mintlang.runtime.testing.running import Options, TestResult, Verdict, run_case

PASSED, FAILED, USAGE, NO_TESTS = 0, 1, 2, 5


@click.command("test", context_settings=HELP_OPTIONS)
@click.argument("paths", nargs=-1, type=click.Path(path_type=Path))
@click.option("--controller", help="The controller to simulate (default: the settings file's, else the dialect's).")
@click.option(
    "--dialect",
    type=click.Choice([dialect.value for dialect in SIMULATED]),
    help="The language of the programs (default: each program's settings file's, else v4).",
)
@click.option("--until-ms", type=click.IntRange(min=1), help="End each run after this much simulated time.")
@click.option(
    "--max-wall-s",
    type=click.FloatRange(min=0, min_open=True),
    default=60.0,
    show_default=True,
    help="Stop a run that takes longer than this on the wall clock (it fails).",
)
@drives_option("Start every test with every drive enabled (they start disabled, as at power-up).")
@click.option("--coverage", is_flag=True, help="Measure line, branch and event-handler coverage: a table, and --lcov.")
@click.option(
    "--lcov",
    type=click.Path(dir_okay=False, path_type=Path),
    default=Path("lcov.info"),
    show_default=True,
    help="Where --coverage writes its lcov tracefile.",
)
@click.option("-j", "--jobs", type=click.IntRange(min=1), help="Tests run at once (default: every core).")
@click.option("--collect-only", is_flag=True, help="List the tests found (text or json) and run none.")
@format_option(["text", "junit", "json"])
@output_file_option()
@exit_zero_option("Exit 0 even when a test fails.")
@color_option()
@version_option("mint test")
def test(  # noqa: PLR0917 - click passes every option as an argument
    paths: tuple[Path, ...],
    controller: str | None,
    dialect: str | None,
    until_ms: int | None,
    max_wall_s: float,
    drives: str | None,
    coverage: bool,
    lcov: Path,
    jobs: int | None,
    collect_only: bool,
    output_format: str,
    output_file: Path | None,
    exit_zero: bool,
    color: str,
) -> None:
    """Run the Mint programs under PATHS (default: the current folder) that have REM @expect lines or a
    scenario file beside them (cell.scenario.toml for cell.mnt), and report which passed."""
    if collect_only and output_format == "junit":
        raise click.UsageError("--collect-only lists the tests as text or json, not junit")
    cases, unreadable = discover(paths or (Path(),))
    errors = console(color, stderr=True)
    for problem in unreadable:
        errors.print(f"mint test: {problem.path}: {problem.reason}", markup=False)
    if not cases:
        errors.print("mint test: no tests found (programs with REM @expect lines or a .scenario.toml beside them)")
        sys.exit(USAGE if unreadable else NO_TESTS)
    if collect_only:
        with destination(output_file, _fail) as stream:
            stream.write(reports.collected(cases, as_json=output_format == "json"))
        sys.exit(USAGE if unreadable else PASSED)
    enabled = drives == "enabled"
    inputs = [path for case in cases for path in (case.program, case.scenario) if path is not None]
    refuse_overwriting(output_file, inputs, _fail)
    refuse_overwriting(lcov if coverage else None, inputs, _fail)
    options = Options(controller, Dialect(dialect) if dialect else None, until_ms, max_wall_s, enabled, coverage)
    began = time.perf_counter()
    results = map_in_order(
        partial(run_case, options=options), cases, workers=jobs or all_cores(), progress=errors, description="testing"
    )
    seconds = time.perf_counter() - began
    with destination(output_file, _fail) as stream:
        if output_format == "junit":
            stream.write(reports.junit(results, seconds))
        elif output_format == "json":
            stream.write(reports.as_json(results, seconds))
        else:
            reports.text(results, seconds, console(color if output_file is None else "never", file=stream))
    if coverage:
        _coverage(results, lcov, output_format, color)
    if unreadable:
        sys.exit(USAGE)
    passed = all(result.verdict is Verdict.PASSED for result in results)
    sys.exit(PASSED if passed or exit_zero else FAILED)


def _coverage(results: list[TestResult], lcov: Path, output_format: str, color: str) -> None:
    """The table (beside a text report, else on standard error) and the lcov tracefile."""
    files = merge(result.coverage for result in results)
    reports.coverage_table(files, console(color, stderr=output_format != "text"))
    try:
        lcov.write_text(tracefile(files), encoding="utf-8")
    except OSError as error:
        _fail(f"cannot write {lcov}: {error.strerror or error}")


def _fail(message: str) -> NoReturn:
    click.echo(f"mint test: {message}", err=True)
    sys.exit(USAGE)
