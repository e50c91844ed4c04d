"""A MintMT ``Event`` or ``Startup`` line opens a block the controller enters; the code around it only steps
over it (MT-7). Like a v4 label line it holds no statement: a breakpoint there binds to the block's first
statement, and stepping never stops on it."""

from __future__ import annotations

from tests.debugger.conftest import Debug

# Three moves of 5 into a buffer of 4 leave one place free; the first move's end frees a second, which is
# the level, so Event MOVEBUFFERLOW comes (004:109-134, MT-14) while the program waits on line 8.
RESTOCKED = """\
Dim lows
MOVEBUFFERSIZE(0) = 4
MOVEBUFFERLOW(0) = 2
MOVER(0) = 5
MOVER(0) = 5
MOVER(0) = 5
GO(0)
Pause IDLE(0)
lows = lows + 10
Event MOVEBUFFERLOW
  lows = lows + 1
End Event
"""


def test_a_breakpoint_on_an_event_line_stops_when_the_event_comes(debug: Debug) -> None:
    client = debug(RESTOCKED, dialect="mintmt", drives="enabled", breakpoints=(10,))
    client.stopped()
    assert (client.line(), client.values()["lows"], client.evaluate("POS(0)")) == (11, "0", "5")
    assert [frame["name"] for frame in client.frames()] == ["#MOVEBUFFERLOW", "program"]


def test_next_from_the_last_statement_before_an_event_block_runs_to_the_end(debug: Debug) -> None:
    client = debug(RESTOCKED, dialect="mintmt", drives="enabled", breakpoints=(9,))
    client.stopped()
    client.body("next", {"threadId": 1})
    # the main flow steps over the block and the program ends: there is no statement left to stop at
    assert client.event_of("stopped", "terminated")["event"] == "terminated"


# The Startup block runs when the controller powers up (004:128-133), before the program's first line.
STARTED = """\
Dim n
n = n + 1
End
Startup
  OUTX(1) = 1
End Startup
"""


def test_a_breakpoint_on_the_startup_line_stops_at_its_first_statement_before_the_program(debug: Debug) -> None:
    client = debug(STARTED, dialect="mintmt", breakpoints=(4,))
    client.stopped()
    assert (client.line(), client.evaluate("OUT")) == (5, "0")
