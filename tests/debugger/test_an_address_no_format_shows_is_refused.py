"""An expression typed at the debugger addresses a keyword only as its formats do, as a line of the program must.

TIME is written ``TIME = <expression>`` and ``v = TIME``, with no dot parameter (000:16727, 16736-16738): the
guide names no error for ``TIME.2``, and ``mint check`` and ``mint-run`` refuse it as a syntax error (2003),
as they refuse ``ADC[1]``, an addressing its formats do not show (000:702-708). A dot names one axis or
channel (000:677-681), so ``SPEED.5.5`` and ``OUT.1.2`` are refused alike. The debug console, a watch and a
breakpoint's condition said 0 for ``TIME.2``, the value of ``TIME`` with its axis dropped; they now give the
check's error at the column of the text typed.
"""

from __future__ import annotations

import pytest

from tests.debugger.conftest import Debug

PROGRAM = "DIM n\nn = 1\nPRINT n\n"
SYNTAX = "Syntax error: "


@pytest.mark.parametrize(
    ("expression", "column", "why"),
    [
        pytest.param("TIME.2", 5, "TIME takes no axis or channel number", id="a dot on TIME"),
        pytest.param("1 + TIME[2]", 9, "TIME takes no axis or channel number", id="brackets on TIME"),
        pytest.param("SPEED.5.5", 8, "SPEED takes one axis number after its dot", id="two axes after a dot"),
        pytest.param("OUT.1.2", 6, "OUT takes one channel number after its dot", id="two channels after a dot"),
    ],
)
def test_the_console_refuses_it_with_the_checks_syntax_error(
    debug: Debug, expression: str, column: int, why: str
) -> None:
    client = debug(PROGRAM, breakpoints=(2,))
    client.stopped()
    response = client.request("evaluate", {"expression": expression, "context": "repl", "frameId": 1})
    assert not response["success"]
    assert response["message"].startswith(f"column {column}: {SYNTAX}{why}")


def test_a_condition_with_it_leaves_the_breakpoint_unverified(debug: Debug) -> None:
    client = debug(PROGRAM)
    (placed,) = client.set_breakpoints({"line": 2, "condition": "TIME.2 > 0"})
    assert not placed["verified"]
    assert "TIME takes no axis or channel number" in placed["message"]


def test_time_as_its_formats_show_it_is_read(debug: Debug) -> None:
    client = debug(PROGRAM, breakpoints=(2,))
    client.stopped()
    assert client.evaluate("TIME") == "0"  # nothing has waited yet: TIME counts from 0 at the start (000:16751)
