"""Each tool's synopsis in the README names every dialect its ``--dialect`` takes: a reader of ``mint check`` or
``mint-run`` learns there that MintMT is read too (README, "MintMT")."""

from __future__ import annotations

import re
from pathlib import Path

import click
import pytest

from mintlang.cli import main

README = Path(__file__).parents[2] / "README.md"


def _synopsis_dialects(opening: str) -> set[str]:
    """The alternatives of ``--dialect`` in the README's code block that opens with ``opening``."""
    text = README.read_text(encoding="utf-8")
    block = re.search(rf"^{re.escape(opening)} .*?(?=^```)", text, re.MULTILINE | re.DOTALL)
    assert block is not None, f"the README has no synopsis of {opening}"
    found = re.search(r"\[--dialect ([\w|]+)\]", block.group(0))
    assert found is not None, f"the synopsis of {opening} names no --dialect"
    return set(found.group(1).split("|"))


SYNOPSES = [("mint check", "check"), ("mint format", "format"), ("mint-run", "run"), ("mint test", "test")]


@pytest.mark.parametrize(("opening", "command"), SYNOPSES)
def test_the_synopsis_lists_the_dialects_the_option_takes(opening: str, command: str) -> None:
    tool = main.get_command(click.Context(main), command)
    assert tool is not None
    (dialect,) = [parameter for parameter in tool.params if parameter.name == "dialect"]
    assert isinstance(dialect.type, click.Choice)
    assert _synopsis_dialects(opening) == set(dialect.type.choices)
