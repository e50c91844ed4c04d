"""Command-line options that every tool spells the same way."""

from __future__ import annotations

from collections.abc import Callable
from typing import TypeVar

import click

from mintlang.keyworddb.model import Controller

F = TypeVar("F", bound=Callable[..., object])


def controller_option(help_text: str) -> Callable[[F], F]:
    """``--controller``: one of the controllers of the v4 guide, NextMove PCI by default."""
    return click.option(
        "--controller",
        type=click.Choice([controller.value for controller in Controller]),
        default=Controller.NEXTMOVE_PCI.value,
        show_default=True,
        help=help_text,
    )
