"""``next`` on the RETURN of an event handler goes back to what the handler broke in on; another call of a handler
that comes before that statement has passed is an event ``next`` runs through, not a step into it.

#TIMER is called every TIMEREVENT ms (000:16789-16799); an event may run while a PAUSE waits
(000:4393-4394), and the PAUSE holds the program until its condition is true (000:1659-1661).
"""

from __future__ import annotations

from tests.debugger.conftest import Debug

TIMED_PAUSE = """\
DIM n
TIMEREVENT = 50
PAUSE TIME >= 120
n = n + 100
END
#TIMER
  n = n + 1
RETURN
"""


def test_next_over_the_return_runs_the_timers_that_come_while_the_pause_waits(debug: Debug) -> None:
    client = debug(TIMED_PAUSE, breakpoints=(8,))
    client.stopped()
    assert (client.line(), client.evaluate("TIME")) == (8, "50")
    client.set_breakpoints()
    client.step("next")
    # back at the PAUSE, which waits on to 120 ms: the timer of 100 ms runs through, unseen
    assert (client.line(), client.evaluate("TIME"), client.values()["n"]) == (4, "120", "2")
    assert [frame["name"] for frame in client.frames()] == ["program"]


def test_next_inside_a_handler_still_stops_at_its_own_return(debug: Debug) -> None:
    client = debug(TIMED_PAUSE, breakpoints=(7,))
    client.stopped()
    client.set_breakpoints()
    client.step("next")
    assert (client.line(), client.evaluate("TIME")) == (8, "50")
