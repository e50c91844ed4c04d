"""``mint test``: run every Mint program under the given paths that carries its own checks.

Exit status: 0 when every test passed, 1 when one failed or could not be
judged, 2 for a usage problem or a path that cannot be read (the other tests
still run), 5 when no test was found or ``-k`` selected none (as pytest does).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import click

from mintlang.cli.options import (
    HELP_OPTIONS,
    color_option,
    drives_option,
    exclude_options,
    exit_zero_option,
    format_option,
    jobs_option,
    output_file_option,
    refuse_nan_seconds,
    verbosity_options,
    version_option,
)
from mintlang.runtime.dialects import SIMULATED
from mintlang.runtime.hardware import CONTROLLERS


@click.command("test", context_settings=HELP_OPTIONS)
@click.argument("paths", nargs=-1, type=click.Path(path_type=Path))
@click.option(
    "--controller",
    type=click.Choice(CONTROLLERS),
    help="The controller to simulate (default: the settings file's, else the dialect's).",
)
@click.option(
    "--dialect",
    type=click.Choice([dialect.value for dialect in SIMULATED]),
    help="The language of the programs (default: each program's settings file's, else v4).",
)
@click.option("--until-ms", type=click.IntRange(min=1), help="End each run after this much simulated time.")
@click.option(
    "--max-wall-s",
    type=click.FloatRange(min=0, min_open=True),
    callback=refuse_nan_seconds,
    default=60.0,
    show_default=True,
    help="Stop a run that takes longer than this on the wall clock (it fails).",
)
@drives_option("Start every test with every drive enabled (they start disabled, as at power-up).")
@click.option("--coverage", is_flag=True, help="Measure line, branch and event-handler coverage: a table, and --lcov.")
@click.option(
    "--lcov",
    type=click.Path(dir_okay=False, path_type=Path),
    help="Where --coverage writes its lcov tracefile.  [default: lcov.info]",
)
@click.option("--no-config", is_flag=True, help="Run each program alone, without the configuration file beside it.")
@exclude_options()
@jobs_option("Tests run at once, on as many processes.  [default: 0, every core]")
@click.option(
    "-k",
    "keyword",
    metavar="EXPRESSION",
    help="Run only the tests whose path contains these words (any case), joined with and, or, not and brackets, "
    "as pytest's -k: -k 'conveyor and not slow'.",
)
@click.option("--collect-only", is_flag=True, help="List the tests found (text or json) and run none.")
@format_option(["text", "junit", "json"])
@output_file_option()
@exit_zero_option("Exit 0 even when a test fails.")
@color_option()
@verbosity_options(
    quiet="Report only the tests that did not pass: no closing count, no progress bar.",
    verbose="Show every expectation under its test, held or not.",
)
@version_option("mint test")
def test(**options: Any) -> None:
    """Run the Mint programs under PATHS (default: the current folder) that have REM @expect lines or a
    scenario file beside them (cell.scenario.toml for cell.mnt), and report which passed. REM @sim and @expect
    lines in a program's configuration file are not read: each is a warning."""
    from mintlang.runtime.testing.testing_command import execute  # noqa: PLC0415 - the simulator, for a run only

    execute(**options)
