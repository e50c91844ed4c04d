"""A tool's own lines (``Messages``) read the same whether rich writes them or, into a pipe, the tool itself.

Into a file or pipe, where rich shows no colour, a printable line is written as it is without
importing rich; a line rich would change (a tab it expands, a control character it drops)
still goes through rich, and colour, when asked for, comes from rich.
"""

from __future__ import annotations

import io
from collections.abc import Callable
from contextlib import redirect_stderr

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from mintlang.cli.terminal import Messages

STYLES = ("", "green", "bold red")


@pytest.fixture(autouse=True)
def _no_forced_colour(monkeypatch: pytest.MonkeyPatch) -> None:
    for name in ("FORCE_COLOR", "TTY_COMPATIBLE", "NO_COLOR"):
        monkeypatch.delenv(name, raising=False)


def written(write: Callable[[], None]) -> str:
    """What ``write`` sends to standard error, which is a pipe here (a ``StringIO`` is no terminal)."""
    stream = io.StringIO()
    with redirect_stderr(stream):
        write()
    return stream.getvalue()


def test_a_plain_line_is_written_as_it_is() -> None:
    assert written(lambda: Messages("auto", stderr=True).line("end after 5 ms", "green")) == "end after 5 ms\n"


def test_a_tab_is_expanded_to_the_next_stop_of_eight_as_rich_does() -> None:
    assert written(lambda: Messages("auto", stderr=True).line("a\tb")) == "a       b\n"


def test_colour_asked_for_comes_from_rich() -> None:
    line = written(lambda: Messages("always", stderr=True).line("error after 5 ms", "bold red"))
    assert line.startswith("\x1b[")
    assert "error after 5 ms" in line


@settings(max_examples=300, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(text=st.text(), style=st.sampled_from(STYLES))
def test_a_line_into_a_pipe_reads_as_rich_writes_it(text: str, style: str) -> None:
    plain = written(lambda: Messages("auto", stderr=True).line(text, style))
    through_rich = written(lambda: Messages("auto", stderr=True, rich=True).line(text, style))
    assert plain == through_rich
