"""``n = 5`` typed in the debug console is refused with where to set a variable, not shown as a comparison.

In an expression Mint's ``=`` compares, giving 1 or 0 (000:1254-1266), so evaluating ``n = 5`` as the watch
and hover contexts do gives 0 or 1, which a user typing it at the console did not ask for. mint-dap runs no
statements, so the console says an assignment goes through the Variables view (setVariable).
"""

from __future__ import annotations

import pytest

from tests.debugger.conftest import Debug

PROGRAM = "DIM n\nn = 1\nPRINT n\n"


@pytest.mark.parametrize(
    "text",
    [
        pytest.param("n = 5", id="variable"),
        pytest.param("SPEED.0 = 10", id="keyword"),
        pytest.param("COMMS(1) = 2", id="comms-element"),
    ],
)
def test_the_console_refuses_an_assignment_and_names_set_variable(debug: Debug, text: str) -> None:
    client = debug(PROGRAM, breakpoints=(3,))
    client.stopped()
    response = client.request("evaluate", {"expression": text, "context": "repl", "frameId": 1})
    assert not response["success"]
    assert response["message"].startswith(f"{text} is an assignment")
    assert "setVariable" in response["message"]
    assert client.values()["n"] == "1"


def test_a_watch_still_reads_it_as_a_comparison(debug: Debug) -> None:
    client = debug(PROGRAM, breakpoints=(3,))
    client.stopped()
    assert (client.evaluate("n = 5"), client.evaluate("n = 1")) == ("0", "1")


def test_the_console_still_evaluates_a_comparison_in_brackets(debug: Debug) -> None:
    client = debug(PROGRAM, breakpoints=(3,))
    client.stopped()
    response = client.body("evaluate", {"expression": "(n = 1)", "context": "repl", "frameId": 1})
    assert response["result"] == "1"
