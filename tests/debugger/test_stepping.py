"""Stepping over, into and out of GOSUBs and event handlers, past a blocked statement, and pausing a running program."""

from __future__ import annotations

from tests.debugger.conftest import Debug

CALLS = """\
DIM x
GOSUB outer
x = x + 100
END
#outer
  x = x + 1
  GOSUB inner
  x = x + 10
RETURN
#inner
  x = x * 2
RETURN
"""


def test_next_runs_a_gosub_through_and_step_in_enters_it(debug: Debug) -> None:
    client = debug(CALLS, breakpoints=(2,))
    client.stopped()
    client.step("next")
    assert (client.line(), client.values()["x"]) == (3, "12")  # (0 + 1) * 2 + 10
    client.step("stepBack")
    client.step("stepIn")
    assert client.line() == 6
    assert [frame["name"] for frame in client.frames()] == ["#outer", "program"]


EVENT_FIRST = """\
DIM hits
Event Comms1
  hits = hits + 1
End Event
REM @sim host write 1 "7" at 5
Loop
  If hits > 0 Then Exit
End Loop
Print hits
"""


def test_the_program_after_a_mintmt_event_block_is_the_program_not_the_handler(debug: Debug) -> None:
    # An Event block ends at its End Event: the code after it is the main program, which steps over the block
    # (MT-7), and the host's write to comms location 1 calls it (002:77-86)
    client = debug(EVENT_FIRST, dialect="mintmt", breakpoints=(3, 9))
    client.stopped()
    assert [frame["name"] for frame in client.frames()] == ["#Comms1", "program"]
    client.step("continue")
    assert [(frame["name"], frame["line"]) for frame in client.frames()] == [("program", 9)]


def test_the_stack_shows_each_gosub_with_the_line_it_was_called_from(debug: Debug) -> None:
    client = debug(CALLS, breakpoints=(11,))
    client.stopped()
    frames = client.frames()
    assert [(frame["name"], frame["line"]) for frame in frames] == [("#inner", 11), ("#outer", 7), ("program", 2)]
    assert all(frame["source"]["name"] == "program.mnt" for frame in frames)


def test_step_out_stops_in_the_caller_after_the_gosub(debug: Debug) -> None:
    client = debug(CALLS, breakpoints=(11,))
    client.stopped()
    client.step("stepOut")
    assert (client.line(), client.values()["x"]) == (8, "2")
    client.step("stepOut")
    assert (client.line(), client.values()["x"]) == (3, "12")


HANDLED = """\
DIM v
DIM x
x = POS.12
PRINT "after"
END
#ONERROR
  PRINT "error "; ERR
RETURN
"""


def test_step_in_follows_an_error_into_onerror_and_out_again(debug: Debug) -> None:
    client = debug(HANDLED, breakpoints=(3,))
    client.stopped()
    client.step("stepIn")
    assert client.line() == 7
    assert [frame["name"] for frame in client.frames()] == ["#ONERROR", "program"]
    client.step("stepOut")
    assert client.line() == 4


def test_next_over_a_wait_stops_once_it_has_passed(debug: Debug) -> None:
    client = debug("DIM a\nWAIT = 30\na = 1\n", breakpoints=(2,))
    client.stopped()
    client.step("next")
    assert client.line() == 3
    assert float(client.evaluate("TIME")) >= 30


def test_pause_stops_a_running_program_where_it_is(debug: Debug) -> None:
    client = debug("DIM n\nLOOP\n  n = n + 1\nENDL\n")
    client.body("pause", {"threadId": 1})
    assert client.stopped()["reason"] == "pause"
    assert client.line() in (1, 2, 3, 4)  # on a busy machine the pause may come before the first statement ran
    assert int(client.values()["n"]) >= 0
    client.body("terminate", {})
    client.event("terminated")


def test_the_program_runs_as_one_thread(debug: Debug) -> None:
    client = debug(CALLS, stopOnEntry=True)
    client.stopped()
    assert client.body("threads")["threads"] == [{"id": 1, "name": "program.mnt"}]


MOVING = """\
DIM n
MOVEA.0 = 1000 : GO.0
PAUSE IDLE.0
n = POS.0
"""


def test_run_for_runs_on_for_a_simulated_time_and_stops_at_the_statement_then_tried(debug: Debug) -> None:
    client = debug(MOVING, breakpoints=(3,), drives="enabled")
    client.stopped()
    started = int(client.evaluate("TIME"))
    client.body("runFor", {"ms": 25})
    assert client.stopped()["reason"] == "step"
    assert client.line() == 3  # the PAUSE, still waiting for the move
    assert int(client.evaluate("TIME")) == started + 25  # the move keeps every tick processed
    assert 0 < float(client.evaluate("POS.0")) < 1000


def test_run_for_takes_a_whole_number_of_milliseconds(debug: Debug) -> None:
    client = debug(MOVING, breakpoints=(3,), drives="enabled")
    client.stopped()
    refused = client.request("runFor", {"ms": 0.5})
    assert not refused["success"] and "whole number" in refused["message"]


def test_a_line_of_several_statements_is_stepped_one_statement_at_a_time_at_its_column(debug: Debug) -> None:
    client = debug("DIM a\nDIM b\na = 1 : b = a + 1\nPRINT b\n", breakpoints=(3,))
    client.stopped()
    assert (client.frames()[0]["line"], client.frames()[0]["column"]) == (3, 1)
    client.step("next")
    assert (client.frames()[0]["line"], client.frames()[0]["column"], client.values()["a"]) == (3, 9, "1")
    client.step("next")
    assert (client.frames()[0]["line"], client.frames()[0]["column"]) == (4, 1)
