"""``mint-dap`` (also ``mint dap``): the Mint debug adapter, speaking DAP on stdin and stdout.

An editor starts it and talks to it; there is nothing to type. Its own
problems go to stderr, which editors show in their logs.
"""

from __future__ import annotations

import sys

import click

from mintlang.cli.options import HELP_OPTIONS, version_option


@click.command(name="dap", context_settings=HELP_OPTIONS)
@version_option("mint-dap")
def dap() -> None:
    """The Mint debug adapter: run a program on the simulator under an editor's debugger (DAP over stdio).

    Breakpoints (conditions, hit counts, log messages), stepping into and out of GOSUBs and event handlers,
    stepping back and reverse-continue, variables, arrays, axes, I/O and the comms array.
    """
    from mintlang.runtime.debugger.session import Session  # noqa: PLC0415  (--help stays fast)

    Session(sys.stdin.buffer, sys.stdout.buffer).serve()


def main() -> None:
    """Entry point of the ``mint-dap`` script."""
    dap()
