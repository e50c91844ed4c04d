"""The ``mint`` command.

``mint check`` lives in the core. The tools add their own subcommands
(``mint migrate``, ``mint run``, ``mint lsp``) through the ``mintlang.commands`` entry-point
group, so the core never imports them; they are loaded only when ``mint``
runs, so importing this package imports no tool.
"""

from __future__ import annotations

import click

from mintlang.cli.check import check
from mintlang.cli.options import HELP_OPTIONS, version_option
from mintlang.cli.rule import rule


class _Commands(click.Group):
    """The core's commands plus those the installed tools register."""

    def _tools(self) -> dict[str, click.Command]:
        from importlib.metadata import entry_points  # noqa: PLC0415 - a tenth of the start-up, paid only for a tool

        return {entry.name: entry.load() for entry in entry_points(group="mintlang.commands")}

    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted({*super().list_commands(ctx), *self._tools()})

    def get_command(self, ctx: click.Context, cmd_name: str) -> click.Command | None:
        return super().get_command(ctx, cmd_name) or self._tools().get(cmd_name)


@click.group(cls=_Commands, context_settings=HELP_OPTIONS)
@version_option("mint")
def main() -> None:
    """Tools for Mint, the motion-control language of Baldor/ABB controllers."""


main.add_command(check)
main.add_command(rule)
