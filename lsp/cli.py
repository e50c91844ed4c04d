"""``mint-lsp [--tcp PORT]`` (also ``mint lsp``): stdio by default, or TCP on 127.0.0.1."""

from __future__ import annotations

import logging
import sys

import click

from mintlang.allocation import no_collection_at_exit
from mintlang.cli.options import HELP_OPTIONS, refuse_quiet_and_verbose, verbosity_options, version_option


@click.command(name="lsp", context_settings=HELP_OPTIONS)
@click.option("--tcp", "port", type=click.IntRange(1, 65535), help="Listen on 127.0.0.1:PORT instead of stdio.")
@click.option("--log-level", type=click.Choice(["debug", "info", "warning", "error"]), default="warning")
@click.option("--log-file", type=click.Path(dir_okay=False), help="Log here instead of stderr.")
@verbosity_options(quiet="Log errors only (--log-level error).", verbose="Log everything (--log-level debug).")
@version_option("mint-lsp")
def lsp(port: int | None, log_level: str, log_file: str | None, quiet: bool, verbose: bool) -> None:
    """The Mint language server: diagnostics, hover, completion, navigation and formatting for Mint programs."""
    refuse_quiet_and_verbose(quiet, verbose)
    log_level = "error" if quiet else "debug" if verbose else log_level
    try:
        logging.basicConfig(
            filename=log_file,
            level=log_level.upper(),
            format="%(asctime)s mint-lsp %(levelname)s %(name)s: %(message)s",
        )
    except OSError as error:
        raise click.BadParameter(f"cannot write {log_file}: {error.strerror}", param_hint="--log-file") from None
    from mintlang.lsp.server import create_server  # noqa: PLC0415  (--help stays fast)

    server = create_server()
    if port is None:
        server.start_io()
        return
    try:
        server.start_tcp("127.0.0.1", port)
    except OSError as error:
        click.echo(f"mint-lsp: cannot listen on 127.0.0.1:{port}: {error.strerror}", err=True)
        sys.exit(2)


def main() -> None:
    """Entry point of the ``mint-lsp`` script."""
    no_collection_at_exit()
    lsp()
