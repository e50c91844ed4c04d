"""A PAUSE or WAIT that an event handler interrupts is still one pass over its line: the statement tried
again once the handler returns is the same wait, not a new arrival at its breakpoint or a stop for ``next``."""

from __future__ import annotations

from tests.debugger.conftest import Debug

# #TIMER runs every TIMEREVENT ms (000:16789-16799), and an event may run while PAUSE or WAIT waits
# (000:4393-4395, 17338-17339); PAUSE holds the program until its condition is true (000:1659-1661).
TIMED_PAUSE = """\
DIM n
TIMEREVENT = 50
PAUSE TIME >= 200
n = n + 100
END
#TIMER
  n = n + 1
RETURN
"""


def test_a_breakpoint_on_a_pause_is_not_hit_again_after_each_event_it_waits_through(debug: Debug) -> None:
    client = debug(TIMED_PAUSE, breakpoints=(3, 4))
    client.stopped()
    assert (client.line(), client.evaluate("TIME")) == (3, "0")
    client.step("continue")
    # the timer served at 50, 100, 150 and 200 ms; the PAUSE passes at 200 ms
    assert (client.line(), client.evaluate("TIME"), client.values()["n"]) == (4, "200", "4")


TIMED_WAIT = """\
DIM n
TIMEREVENT = 50
WAIT = 120
n = n + 100
END
#TIMER
  n = n + 1
RETURN
"""


def test_next_over_a_wait_that_events_interrupt_stops_once_it_has_passed(debug: Debug) -> None:
    client = debug(TIMED_WAIT, breakpoints=(3,))
    client.stopped()
    client.step("next")
    # WAIT = 120 from 0 ms ends at 120 ms (000:17338-17339); the timer ran at 50 and 100 ms
    assert (client.line(), client.evaluate("TIME"), client.values()["n"]) == (4, "120", "2")
