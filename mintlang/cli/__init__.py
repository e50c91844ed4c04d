"""The ``mint`` command.

``mint check`` lives in the core. The tools add their own subcommands
(``mint migrate``, ``mint run``) through the ``mintlang.commands`` entry-point
group, so the core never imports them.
"""

from __future__ import annotations

from importlib.metadata import entry_points

import click

from mintlang.cli.check import check


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(package_name="mintlang")
def main() -> None:
    """Tools for Mint, the motion-control language of Baldor/ABB controllers."""


main.add_command(check)
for _entry in entry_points(group="mintlang.commands"):
    main.add_command(_entry.load(), _entry.name)
