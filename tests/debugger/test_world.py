"""Changing the world while paused: an input wired on or off, keys typed at the controller's keyboard.

Each is an intervention (``runtime/debugger/history.py``): a re-run through the
point makes it again, and going back before it undoes it.
"""

from __future__ import annotations

from tests.debugger.conftest import Debug

WAITS_FOR_INPUT = """\
DIM a
PAUSE IN.3
a = 1
PRINT "through"
"""


def _inputs(client) -> int:
    (bank,) = [
        v
        for v in client.body("variables", {"variablesReference": client.scope("I/O")})["variables"]
        if v["name"] == "IN"
    ]
    return bank["variablesReference"]


def test_an_input_set_while_paused_lets_a_pause_on_it_pass(debug: Debug) -> None:
    client = debug(WAITS_FOR_INPUT, breakpoints=(2,))
    client.stopped()
    inputs = _inputs(client)
    assert client.variables(inputs)["IN.3"] == "0"
    assert client.body("setVariable", {"variablesReference": inputs, "name": "IN.3", "value": "1"})["value"] == "1"
    assert client.variables(client.scope("I/O"))["IN"].endswith("(8)")
    client.step("next")
    assert client.line() == 3
    client.body("continue", {"threadId": 1})
    client.event("terminated")
    assert client.output() == "through\n"


def test_going_back_before_an_input_was_set_unsets_it(debug: Debug) -> None:
    client = debug(WAITS_FOR_INPUT, breakpoints=(2,))
    client.stopped()
    client.body("setVariable", {"variablesReference": _inputs(client), "name": "IN.3", "value": "1"})
    client.step("next")
    client.step("stepBack")
    assert client.variables(client.scope("I/O"))["IN"].endswith("(8)")  # back at the point it was set
    client.step("stepBack")
    assert (client.line(), client.variables(client.scope("I/O"))["IN"].endswith("(0)")) == (1, True)


def test_an_input_is_zero_or_one(debug: Debug) -> None:
    client = debug(WAITS_FOR_INPUT, breakpoints=(2,))
    client.stopped()
    refused = client.request("setVariable", {"variablesReference": _inputs(client), "name": "IN.3", "value": "2"})
    assert not refused["success"] and "0 or 1" in refused["message"]


def test_keys_typed_in_the_debug_console_are_what_inkey_reads_next(debug: Debug) -> None:
    client = debug("DIM k\nDIM j\nk = INKEY\nj = INKEY\nPRINT k, j\n", breakpoints=(3,))
    client.stopped()
    typed = client.body("evaluate", {"expression": '"ab"', "context": "repl", "frameId": 1})
    assert typed["result"] == "typed 2 keys"
    client.step("next")
    client.step("next")
    assert client.values() == {"j": "66", "k": "65"}  # INKEY upper-cases a to z


def test_one_key_typed_is_said_in_the_singular(debug: Debug) -> None:
    client = debug("DIM k\nk = INKEY\nPRINT k\n", breakpoints=(2,))
    client.stopped()
    typed = client.body("evaluate", {"expression": '"Q"', "context": "repl", "frameId": 1})
    assert typed["result"] == "typed 1 key"


def test_a_quoted_string_in_a_watch_is_not_typed(debug: Debug) -> None:
    client = debug("DIM k\nk = INKEY\nPRINT k\n", breakpoints=(2,))
    client.stopped()
    assert not client.request("evaluate", {"expression": '"a"', "context": "watch", "frameId": 1})["success"]
    client.step("next")
    assert client.values() == {"k": "0"}
