"""``mint-migrate`` (also ``mint migrate``): migrate Mint v3 files to Mint v4.

Default is a dry run that prints a unified diff and the report (``--diff``
names it, as ``mint check --diff`` and ruff spell it). ``--write``
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

from pathlib import Path
from typing import Any

import click

from mintlang.allocation import collector_paused_and_kept, no_collection_at_exit
from mintlang.cli.options import (
    HELP_OPTIONS,
    color_option,
    controller_option,
    drives_option,
    exclude_options,
    exit_zero_option,
    format_option,
    list_option,
    output_file_option,
    refuse_settings_file,
    verbosity_options,
    version_option,
)
from mintlang.cli.settings import ProjectCommand
from mintlang.migrate.verification.model import DEFAULT_UNTIL_MS
from mintlang.runtime.dialects.v3.controllers import DEFAULT as V3_DEFAULT
from mintlang.runtime.dialects.v3.controllers import PROFILES as V3_CONTROLLERS

EXIT_STATUS = """\b
Exit status:
  0  done: nothing left to rewrite (--check), everything written or
     printed, or every application verified equivalent (--verify; a
     timing difference X-GO-TIMING flagged counts as a manual item, and
     values M-TRIG says differ are explained differences);
     manual items are reported and do not fail a run
  1  the gate failed: --check found something to rewrite, --verify found
     a divergence, or manual items are left and --fail-on manual was given
  2  something was not done: a usage error, a file that cannot be read
     or written, a file that changed since it was read (not written), a
     rule that failed on a file (that file is left as it was; the others
     are migrated and written), or a --verify comparison that could not
     cover the run (incomplete)
  141  the reader of standard output went away (| head)"""


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
@click.option("--diff", is_flag=True, help="Print the changes as a unified diff; write nothing (the default).")
@click.option("--check", is_flag=True, help="Exit 1 when anything would be rewritten; write nothing.")
@click.option("--stdout", "to_stdout", is_flag=True, help="Print the migrated text of one file.")
@click.option(
    "--config",
    "config",
    type=click.Path(path_type=Path),
    help="Configuration file migrated together with the program (its variables are visible there).",
    callback=refuse_settings_file,
)
@click.option(
    "--no-config",
    is_flag=True,
    help="Pair no configuration file with the programs: each file is migrated (and verified) alone.",
)
@click.option(
    "--to",
    "to",
    type=click.Choice(["v4", "mintmt"]),
    default="v4",
    show_default=True,
    help="The dialect to migrate to: v4 reads the files as Mint v3, mintmt reads them as Mint v4.",
)
@controller_option("The controller to migrate to (with --to mintmt, the one both runs of --verify use).")
@format_option(["text", "json"])
@output_file_option("Write the diff and the report to this file instead of standard output.")
@click.option("--fail-on", "fail_on", type=click.Choice(["manual"]), help="Exit 1 when manual items are left.")
@exit_zero_option("Exit with 0 when the gate fails (--check, --verify, --fail-on); 2 still means not done.")
@exclude_options()
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
    help="Run each original application (v3, or v4 with --to mintmt) and its migration in the simulator and "
    "compare them; write nothing.",
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
def migrate(**options: Any) -> None:
    """Migrate Mint v3 programs (.mnt) and configuration files (.cfg) to Mint v4, or v4 ones to MintMT
    (--to mintmt)."""
    with collector_paused_and_kept():  # its modules live as long as the process: no collection walks them
        from mintlang.migrate.migrate_command import execute  # noqa: PLC0415 - the rules, for a migration only

    execute(**options)


def main() -> None:
    """Entry point of the ``mint-migrate`` script."""
    no_collection_at_exit()
    migrate()
