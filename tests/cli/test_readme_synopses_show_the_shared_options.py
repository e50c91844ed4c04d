"""Each tool's synopsis in the README shows the shared options the tool takes, and points to their table right
below it: a reader of one section learns there that ``--format``, ``--quiet`` and the rest apply (README,
"Options every tool shares")."""

from __future__ import annotations

import re
from pathlib import Path

import click
import pytest

from mintlang.cli import main

README = Path(__file__).parents[2] / "README.md"
TABLE_LINK = "(#options-every-tool-shares)"
SHARED = {"--format", "--output-file", "--exit-zero", "--color", "--quiet", "--verbose"}
SHARED |= {"--exclude", "--extend-exclude", "--force-exclude"}
"""The options of ``mintlang/cli/options.py`` that several tools share (``--version`` and ``-h`` aside)."""

SYNOPSES = [
    ("mint check", "check"),
    ("mint format", "format"),
    ("mint rule", "rule"),
    ("mint-migrate", "migrate"),
    ("mint-run", "run"),
    ("mint test", "test"),
    ("mint-lsp", "lsp"),
]


def _synopsis(opening: str) -> tuple[str, str]:
    """The README's code block that opens with ``opening``, and the text that follows it."""
    text = README.read_text(encoding="utf-8")
    block = re.search(rf"^```\n({re.escape(opening)} .*?)^```\n", text, re.MULTILINE | re.DOTALL)
    assert block is not None, f"the README has no synopsis of {opening}"
    return block.group(1), text[block.end() : block.end() + 400]


def _shared_parameters(command: str) -> list[click.Parameter]:
    tool = main.get_command(click.Context(main), command)
    assert tool is not None
    return [parameter for parameter in tool.params if SHARED & set(parameter.opts)]


@pytest.mark.parametrize(("opening", "command"), SYNOPSES)
def test_the_synopsis_names_every_shared_option_the_tool_takes(opening: str, command: str) -> None:
    synopsis, _ = _synopsis(opening)
    written = set(re.findall(r"(?<![\w-])--?[a-z][\w-]*", synopsis))
    missing = [parameter.opts[0] for parameter in _shared_parameters(command) if not written & set(parameter.opts)]
    assert missing == [], f"the synopsis of {opening} leaves out {missing}"


@pytest.mark.parametrize("opening", [opening for opening, _ in SYNOPSES])
def test_the_synopsis_points_to_the_shared_options_table(opening: str) -> None:
    _, after = _synopsis(opening)
    paragraph = after.strip("\n").split("\n\n", 1)[0]
    assert TABLE_LINK in paragraph, f"the paragraph under the synopsis of {opening} links no table"
