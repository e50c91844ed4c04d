"""The text report looks the same in every colour system, and carries only escape codes beyond the plain text."""

from __future__ import annotations

import io
import re

import pytest
from rich.console import Console

from mintlang.cli.report import FileReport, render_text
from mintlang.diagnostics import Diagnostic, Severity, Span

SOURCE = "DIM a\nPRINT b\n"
REPORT = FileReport("p.mnt", SOURCE, (Diagnostic("E3001", Severity.ERROR, Span(12, 13), "'b' is not declared"),))
SGR = re.compile(r"\x1b\[[0-9;]*m")


def rendered(color_system: str | None) -> str:
    console = Console(file=io.StringIO(), color_system=color_system, force_terminal=True, width=80)
    render_text([REPORT], console.file, console)
    return console.file.getvalue()  # type: ignore[attr-defined]


@pytest.mark.parametrize("color_system", ["standard", "256", "truecolor"])
def test_each_colour_system_colours_the_plain_report(color_system: str) -> None:
    coloured, plain = rendered(color_system), rendered(None)
    assert SGR.search(coloured)
    assert SGR.sub("", coloured) == plain
    assert plain.startswith("error[E3001]: 'b' is not declared\n  --> p.mnt:2:7\n")


def test_no_colour_system_writes_no_escape_codes() -> None:
    assert "\x1b" not in rendered(None)
