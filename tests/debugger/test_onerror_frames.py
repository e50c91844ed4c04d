"""Where the program's frame stands while ``#ONERROR`` runs, and where a step back after it lands.

A move on axis 12 is an 'Invalid axis' system error, which calls ``#ONERROR``
(000:4597-4598, 4616-4619); ERL is the line the error occurred on (000:4698-4700),
and the handler's RETURN goes on after the failing statement (EV-19). The call
stack shows the caller at the statement that called: for a GOSUB the GOSUB, for
``#ONERROR`` the failing statement, the one ERL names. A step back from the
statement after the handler lands on that same failing statement, so the two
views agree.
"""

from __future__ import annotations

from tests.debugger.conftest import Debug
from tests.debugger.test_stepping import HANDLED  # x = POS.12 on line 3; #ONERROR on lines 6-8


def test_the_program_frame_under_onerror_stands_at_the_failing_statement(debug: Debug) -> None:
    client = debug(HANDLED, breakpoints=(7,))
    client.stopped()
    frames = client.frames()
    assert [(frame["name"], frame["line"]) for frame in frames] == [("#ONERROR", 7), ("program", 3)]


def test_a_step_back_after_the_handler_lands_on_the_failing_statement_the_frame_showed(debug: Debug) -> None:
    client = debug(HANDLED, breakpoints=(8,))
    client.stopped()
    client.step("stepOut")
    assert (client.line(), client.evaluate("ERL")) == (4, "3")  # RETURN goes on after line 3, ERL = 3
    client.step("stepBack")
    assert client.line() == 3
