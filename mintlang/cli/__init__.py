"""The ``mint`` command.

``mint check``, ``mint format`` and ``mint rule`` live in the core. The tools add their own subcommands
(``mint migrate``, ``mint run``, ``mint lsp``) through the ``mintlang.commands`` entry-point
group, so the core never imports them; they are loaded only when ``mint``
runs, so importing this package imports no tool. The core's own commands are
imported when named too: ``mint check`` never loads what ``mint rule`` needs.
"""

from __future__ import annotations

from importlib import import_module
from typing import Any

import click

from mintlang.allocation import collector_paused_and_kept, no_collection_at_exit
from mintlang.cli.options import HELP_OPTIONS, version_option

_CORE_COMMANDS = {
    "check": ("mintlang.cli.check", "check"),
    "format": ("mintlang.cli.formatter", "format_command"),
    "rule": ("mintlang.cli.rule", "rule"),
}
"""Each core command: the module that defines it, and its name there."""


class _Commands(click.Group):
    """The core's commands plus those the installed tools register."""

    def _tools(self) -> dict[str, click.Command]:
        from importlib.metadata import entry_points  # noqa: PLC0415 - a tenth of the start-up, paid only for a tool

        return {entry.name: entry.load() for entry in entry_points(group="mintlang.commands")}

    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted({*_CORE_COMMANDS, *self._tools()})

    def main(self, *args: Any, **kwargs: Any) -> Any:
        """click's entry point: the process it runs in exits without a last walk of its objects."""
        no_collection_at_exit()
        return super().main(*args, **kwargs)

    def get_command(self, ctx: click.Context, cmd_name: str) -> click.Command | None:
        defined = _CORE_COMMANDS.get(cmd_name)
        if defined is not None:
            module, name = defined
            with collector_paused_and_kept():  # its modules live as long as the process: no collection walks them
                command: click.Command = getattr(import_module(module), name)
            return command
        return self._tools().get(cmd_name)


@click.group(cls=_Commands, context_settings=HELP_OPTIONS)
@version_option("mint")
def main() -> None:
    """Tools for Mint, the motion-control language of Baldor/ABB controllers."""
