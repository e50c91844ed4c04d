"""``mint-run`` (also ``mint run``): run a Mint program on the simulated controller.

Terminal output goes to stdout as the controller prints it; what stopped the
run goes to stderr. Exit status: 0 when the program ended (or reached
``--until-ms``), 1 when it stopped on an error, a deadlock or the wall-clock
limit, or when an expectation failed; 2 for a usage or I/O problem. ``--dialect v3``
runs a Mint v3 program on one of the v3 guide's controllers. With
``--expect`` the expectations decide 0 or 1 (``expectations_pass``). Ctrl-C
stops the run where it is, still reports it and completes the trace, and
exits 130; SIGTERM does the same with 143, and a reader that goes away
(``| head``) with 141. The trace streams to its file as the run goes, so a
long run's memory does not grow with its length.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import click

from mintlang.allocation import collector_paused_and_kept, no_collection_at_exit
from mintlang.cli.options import (
    HELP_OPTIONS,
    color_option,
    drives_option,
    exit_zero_option,
    refuse_nan_seconds,
    refuse_settings_file,
    verbosity_options,
    version_option,
)
from mintlang.cli.settings import ProjectCommand
from mintlang.dialect import Dialect
from mintlang.runtime.dialects import SIMULATED
from mintlang.runtime.hardware import CONTROLLERS


@click.command(
    cls=ProjectCommand,
    tool="mint-run",
    table="run",  # [tool.mint.run]: defaults for these options
    start=lambda params: params["program"],
    context_settings=HELP_OPTIONS,
)
@click.argument("program", type=click.Path(path_type=Path))
@click.option(
    "--config",
    "config_path",
    type=click.Path(path_type=Path),
    help="Configuration file run before the program (by default the one beside it: <name>.cfg, any case).",
    callback=refuse_settings_file,
)
@click.option("--no-config", is_flag=True, help="Run the program without a configuration file.")
@click.option(
    "--dialect",
    type=click.Choice([dialect.value for dialect in SIMULATED]),
    default=Dialect.V4.value,
    show_default=True,
    help="The language of the program: Mint v4, Mint v3 (the esMINT guide) or MintMT (mintlang/MINTMT.md).",
)
@click.option(
    "--controller",
    type=click.Choice(CONTROLLERS),
    help="The controller to simulate: one of the v4 guide's for v4 (default nextmove-pci), "
    "one of the v3 guide's for v3 (default euroservo).",
)
@click.option(
    "--stimulus",
    "stimulus_paths",
    multiple=True,
    type=click.Path(path_type=Path),
    help="TOML scenario: inputs, keys, host packets, plants (repeatable).",
)
@click.option(
    "--expect",
    "expect_paths",
    multiple=True,
    type=click.Path(path_type=Path),
    help="TOML scenario whose expectations decide the exit status (repeatable).",
)
@drives_option("Start with every drive enabled, as a bench configuration would (they start disabled, as at power-up).")
@click.option("--until-ms", type=click.IntRange(min=0), help="Stop after this much simulated time.")
@click.option(
    "--max-wall-s",
    type=click.FloatRange(min=0),
    callback=refuse_nan_seconds,
    default=60.0,
    show_default=True,
    help="Stop after this much real time (raise it for long --realtime runs; inf for no limit).",
)
@click.option(
    "--trace",
    "trace_path",
    type=click.Path(path_type=Path),
    help="Stream every tick's axis and I/O state to this CSV file as the run goes; complete however the run stops.",
)
@click.option(
    "--plot",
    "plot_path",
    type=click.Path(path_type=Path),
    help="Draw position, velocity and following error to this image (needs matplotlib); "
    "a long run is drawn from each span's extremes, so every peak shows.",
)
@click.option(
    "--trace-axes", help="Axes to trace and plot, e.g. 0,1 (default: every axis traced, those that moved plotted)."
)
@click.option(
    "--format",
    "--output-format",
    "--report",
    "report_format",
    type=click.Choice(["json"]),
    help="Print a report of the final state at the end, after the program's output.",
)
@click.option(
    "--output-file",
    "--report-file",
    "report_path",
    type=click.Path(path_type=Path),
    help="Write the json report to this file, with or without --format.",
)
@click.option("--realtime", is_flag=True, help="Pace the simulation to real time.")
@click.option(
    "--host-port",
    type=click.IntRange(min=0, max=65535),
    help="Serve the host comms protocol on this TCP port of 127.0.0.1.",
)
@exit_zero_option("Exit with 0 when the program stops on an error or an expectation fails (2 still reports misuse).")
@verbosity_options(
    quiet="No progress bar, and no closing line when the program ends normally.",
    verbose="Also say how long the run took in real time, beside the simulated time.",
)
@color_option()
@version_option("mint-run")
def run(**options: Any) -> None:
    """Run a Mint program against simulated axes, I/O and a host.

    Keys piped to standard input (printf '42\\n' | mint-run app.mnt) answer INPUT and INKEY, after any a
    scenario types.

    Ctrl-C (exit 130) or SIGTERM (exit 143) stops the run where it is; the report and the trace are still written.
    """
    with collector_paused_and_kept():  # its modules live as long as the process: no collection walks them
        from mintlang.runtime.run_command import execute  # noqa: PLC0415 - the simulator, for a run only

    execute(**options)


def main() -> None:
    """Entry point of the ``mint-run`` script."""
    no_collection_at_exit()
    run()
