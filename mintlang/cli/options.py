"""Command-line options that every tool spells the same way.

``mint``, ``mint-run``, ``mint-migrate`` and ``mint-lsp`` take their shared
options from here, so ``--format``, ``--output-file``, ``--exit-zero``,
``--color``, ``-q``/``-v``, ``--version`` and ``-h`` mean the same everywhere.
Nothing here imports more than click: ``--version`` and ``--help`` stay fast.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TypeVar

import click

from mintlang import __version__
from mintlang.cli.terminal import COLOR_CHOICES
from mintlang.keyworddb.model import Controller

F = TypeVar("F", bound=Callable[..., object])

HELP_OPTIONS = {"help_option_names": ["-h", "--help"]}
"""The context settings of every command: ``-h`` is ``--help``."""


V3_CHECKED = (
    "checks against the v3 guide's controllers (at most three axes, 8 inputs and outputs); leave --controller out"
)
"""How ``mint check --dialect v3`` treats ``--controller``: there is none to choose."""


class _Controllers(click.Choice):
    """The v4 guide's controllers; one of the v3 guide's (as ``mint-run --dialect v3`` takes) is told how v3 is
    checked, where a list of the v4 ones would send the user to one that ``--dialect v3`` refuses."""

    def convert(self, value: object, param: click.Parameter | None, ctx: click.Context | None) -> object:
        try:
            return super().convert(value, param, ctx)
        except click.BadParameter:
            from mintlang.runtime.dialects.v3.controllers import PROFILES  # noqa: PLC0415 - only on this mistake

            if value in PROFILES:
                self.fail(f"{value} is a controller of the Mint v3 guide: mint check --dialect v3 {V3_CHECKED}")
            raise


def controller_option(help_text: str) -> Callable[[F], F]:
    """``--controller``: one of the controllers of the v4 guide, NextMove PCI by default."""
    return click.option(
        "--controller",
        type=_Controllers([controller.value for controller in Controller]),
        default=Controller.NEXTMOVE_PCI.value,
        show_default=True,
        help=help_text,
    )


def version_option(prog_name: str) -> Callable[[F], F]:
    """``--version``: the distribution's version (nothing of the tool is imported, nor ``importlib.metadata``,
    which would cost a third of ``python -c pass`` more)."""
    return click.version_option(__version__, prog_name=prog_name)


def list_option(*names: str, absent: tuple[str, ...] | None = (), **settings: object) -> Callable[[F], F]:
    """An option taking several values: repeated (``--x A --x B``), comma-separated (``--x A,B``) or both.

    The command receives a tuple of the values (empty for ``--x ""``), or ``absent`` when the option was not given.
    """

    def comma_separated(
        _context: click.Context, _parameter: click.Parameter, values: tuple[str, ...]
    ) -> tuple[str, ...] | None:
        if not values:
            return absent
        return tuple(part.strip() for value in values for part in value.split(",") if part.strip())

    return click.option(*names, multiple=True, callback=comma_separated, **settings)  # type: ignore[call-overload]


def format_option(choices: Sequence[str], help_text: str = "How to write the report.") -> Callable[[F], F]:
    """``--format``: the one spelling of an output format on every tool; the first choice is the default.
    ``--output-format`` is ruff's name for it, accepted alike."""
    return click.option(
        "--format",
        "--output-format",
        "output_format",
        type=click.Choice(list(choices)),
        default=choices[0],
        show_default=True,
        help=help_text,
    )


def output_file_option(
    help_text: str = "Write the report to this file instead of standard output.",
) -> Callable[[F], F]:
    """``--output-file``: the report goes to a file (never coloured unless ``--color always``)."""
    return click.option("--output-file", type=click.Path(dir_okay=False, path_type=Path), help=help_text)


def jobs_option(help_text: str) -> Callable[[F], F]:
    """``-j``/``--jobs``: how many processes work at once; 0, the default, is every core (``check``, ``test``)."""
    return click.option("-j", "--jobs", type=click.IntRange(min=0), default=0, help=help_text)


def exit_zero_option(help_text: str) -> Callable[[F], F]:
    """``--exit-zero``: findings do not fail the run; a usage or I/O problem still does."""
    return click.option("--exit-zero", is_flag=True, help=help_text)


def color_option() -> Callable[[F], F]:
    """``--color``: on a terminal unless NO_COLOR is set (auto), always, or never."""
    return click.option(
        "--color",
        type=click.Choice(COLOR_CHOICES),
        default="auto",
        show_default=True,
        help="Colour the output: on a terminal unless NO_COLOR is set (auto), always, or never.",
    )


def verbosity_options(quiet: str, verbose: str) -> Callable[[F], F]:
    """``-q/--quiet`` and ``-v/--verbose``, with what each leaves out or adds for this tool."""
    quiet_option = click.option("-q", "--quiet", is_flag=True, help=quiet)
    verbose_option = click.option("-v", "--verbose", is_flag=True, help=verbose)

    def decorate(function: F) -> F:
        return quiet_option(verbose_option(function))

    return decorate


def exclude_options() -> Callable[[F], F]:
    """ruff's ``--exclude``, ``--extend-exclude`` and ``--force-exclude``: what the folders searched leave out,
    over the settings of the same names (``cli.settings.exclusions`` reads them)."""
    exclude = list_option(
        "--exclude",
        absent=None,
        metavar="GLOBS",
        help="Leave these files and folders out of the folders searched, instead of the settings' exclude (by"
        " default .git, .venv, build, dist, node_modules and other tools' folders); comma-separated or repeated.",
    )
    extend_exclude = list_option(
        "--extend-exclude", absent=None, metavar="GLOBS", help="Leave these files and folders out too, besides exclude."
    )
    force_exclude = click.option(
        "--force-exclude/--no-force-exclude",
        default=None,
        help="Leave out the excluded paths even when named (as pre-commit names the files it checks).",
    )

    def decorate(function: F) -> F:
        return exclude(extend_exclude(force_exclude(function)))

    return decorate


def refuse_quiet_and_verbose(quiet: bool, verbose: bool) -> None:
    if quiet and verbose:
        raise click.UsageError("--quiet and --verbose: choose one")


def drives_option(help_text: str) -> Callable[[F], F]:
    """``--drives enabled``: the simulated drives start enabled (they start disabled, as at power-up)."""
    return click.option("--drives", type=click.Choice(["enabled"]), help=help_text)


def refuse_nan_seconds(_context: click.Context, _parameter: click.Parameter, seconds: float) -> float:
    """``--max-wall-s``'s callback: NaN passes a ``FloatRange`` (every comparison with it is false), and as a limit
    no elapsed time exceeds it, so the run would never stop."""
    if math.isnan(seconds):
        raise click.BadParameter("give a number of seconds, or inf for no limit")
    return seconds


def refuse_settings_file(_context: click.Context, _parameter: click.Parameter, path: Path | None) -> Path | None:
    """``--config``'s callback: it names the Mint configuration file a program sees, where ruff's names the
    settings file; a ``mint.toml`` read as Mint would be nothing but syntax errors."""
    if path is not None and path.suffix.lower() == ".toml":
        raise click.BadParameter(
            f"{path} is a settings file, found above each program without being named; "
            "--config names the Mint configuration file (.cfg) the programs see"
        )
    return path
