"""A MintMT ``Event`` or ``Startup`` line opens a block the controller enters; the code around it only steps
over it (MT-7). Like a v4 label line it holds no statement: a breakpoint there binds to the block's first
statement, and stepping never stops on it."""

from __future__ import annotations

from tests.debugger.conftest import Debug
from tests.debugger.test_breakpoints import RESTOCKED  # Event MOVEBUFFERLOW on line 10, its block lines 11-12


def test_a_breakpoint_on_an_event_line_stops_when_the_event_comes(debug: Debug) -> None:
    # The first move's end frees the second of four places, the level: the event comes (004:109-134, MT-14)
    client = debug(RESTOCKED, dialect="mintmt", drives="enabled", breakpoints=(10,))
    client.stopped()
    assert (client.line(), client.values()["lows"], client.evaluate("POS(0)")) == (11, "0", "5")
    assert [frame["name"] for frame in client.frames()] == ["#MOVEBUFFERLOW", "program"]


# The Startup block runs when the controller powers up (004:128-133), before the program's first line; the
# host's writes to comms location 1 call Event Comms1 (002:77-86). Neither block is entered from line 2.
BLOCKS_AFTER = """\
Dim n
n = n + 1
Event Comms1
  n = 0
End Event
Startup
  OUTX(1) = 1
End Startup
"""


def test_next_from_the_last_statement_before_the_blocks_runs_to_the_end(debug: Debug) -> None:
    client = debug(BLOCKS_AFTER, dialect="mintmt", breakpoints=(2,))
    client.stopped()
    client.body("next", {"threadId": 1})
    # the main flow steps over both blocks and the program ends: no statement is left to stop at
    assert client.event_of("stopped", "terminated")["event"] == "terminated"


def test_a_breakpoint_on_the_startup_line_stops_at_its_first_statement_before_the_program(debug: Debug) -> None:
    client = debug(BLOCKS_AFTER, dialect="mintmt", breakpoints=(6,))
    client.stopped()
    assert (client.line(), client.evaluate("OUT")) == (7, "0")
