"""Line breakpoints: where they bind, conditions, hit counts and log messages."""

from __future__ import annotations

import pytest

from tests.debugger.conftest import Debug

PROGRAM = """\
DIM i
DIM s

REM the loop
FOR i = 1 TO 4
  s = s + i : PRINT s
NEXT
END
"""


def test_a_breakpoint_on_a_line_without_a_statement_binds_to_the_next_that_has_one(debug: Debug) -> None:
    client = debug(PROGRAM)
    placed = client.set_breakpoints(3, 4, 9)
    assert [(item["verified"], item["line"]) for item in placed] == [(True, 5), (True, 5), (False, 9)]
    assert "no statement" in placed[2]["message"]


MALFORMED = [
    pytest.param({"line": -3}, "not -3", id="a line before the first"),
    pytest.param({"line": 0}, "not 0", id="line 0, the client counting lines from 1"),
    pytest.param({"line": "6"}, "not '6'", id="a line written as text"),
    pytest.param({}, "not None", id="no line"),
    pytest.param({"line": 6, "condition": 5}, "'condition' is text", id="a condition that is not text"),
    pytest.param({"line": 6, "hitCondition": 3}, "'hitCondition' is text", id="a hit condition that is not text"),
    pytest.param({"line": 6, "logMessage": 7}, "'logMessage' is text", id="a log message that is not text"),
]


@pytest.mark.parametrize(("malformed", "why"), MALFORMED)
def test_a_breakpoint_it_cannot_set_is_unverified_and_the_requests_others_are_set(
    debug: Debug, malformed: dict[str, object], why: str
) -> None:
    """The response has one breakpoint per one asked for, in their order: a bad one fails alone."""
    client = debug(PROGRAM, stopOnEntry=True)
    client.stopped()
    bad, good = client.set_breakpoints(malformed, 6)
    assert (bad["verified"], good["verified"], good["line"]) == (False, True, 6)
    assert why in bad["message"]
    assert client.step("continue")["reason"] == "breakpoint"
    assert client.line() == 6


def test_a_breakpoint_stops_once_per_pass_over_its_line(debug: Debug) -> None:
    client = debug(PROGRAM, breakpoints=(6,))
    hits = []
    for _ in range(4):
        assert client.stopped()["reason"] == "breakpoint"
        hits.append(client.values()["s"])
        client.body("continue", {"threadId": 1})
    client.event("terminated")
    assert hits == ["0", "1", "3", "6"]


def test_a_conditional_breakpoint_stops_only_where_its_mint_expression_is_true(debug: Debug) -> None:
    client = debug(PROGRAM, breakpoints=({"line": 6, "condition": "i = 3 OR s > 100"},))
    client.stopped()
    assert client.values() == {"i": "3", "s": "3"}
    client.body("continue", {"threadId": 1})
    client.event("terminated")


HIT_CONDITIONS = [("3", ["3"]), ("== 2", ["2"]), (">= 3", ["3", "4"]), ("% 2", ["2", "4"]), ("< 2", ["1"])]


@pytest.mark.parametrize(("hit_condition", "stops"), HIT_CONDITIONS)
def test_a_hit_condition_stops_at_the_hits_its_count_picks(debug: Debug, hit_condition: str, stops: list[str]) -> None:
    client = debug(PROGRAM, breakpoints=({"line": 6, "hitCondition": hit_condition},))
    seen = []
    while client.event_of("stopped", "terminated")["event"] == "stopped":
        seen.append(client.values()["i"])
        client.body("continue", {"threadId": 1})
    assert seen == stops


def test_the_editor_resending_a_files_breakpoints_keeps_the_hits_counted_so_far(debug: Debug) -> None:
    client = debug(PROGRAM, breakpoints=({"line": 6, "hitCondition": ">= 2"},))
    client.stopped()
    assert client.values()["i"] == "2"
    client.set_breakpoints({"line": 6, "hitCondition": ">= 2"}, 8)
    client.step("continue")
    assert client.values()["i"] == "3"


def test_a_hit_condition_it_cannot_read_leaves_the_breakpoint_unverified(debug: Debug) -> None:
    client = debug(PROGRAM)
    (placed,) = client.set_breakpoints({"line": 6, "hitCondition": "often"})
    assert not placed["verified"]
    assert "hit condition" in placed["message"]


def test_a_log_message_prints_its_values_and_does_not_stop(debug: Debug) -> None:
    client = debug(PROGRAM, breakpoints=({"line": 6, "logMessage": "i={i}, s doubled={s * 2}"},))
    client.event("terminated")
    logged = [body["output"] for body in client.outputs() if body["category"] == "console"]
    assert logged[:4] == ["i=1, s doubled=0\n", "i=2, s doubled=2\n", "i=3, s doubled=6\n", "i=4, s doubled=12\n"]
    assert client.output().split() == ["1", "3", "6", "10"]


UNREADABLE_CONDITIONS = [
    pytest.param("i >", "column 4", id="an expression cut short"),
    pytest.param("nosuch > 1", "nosuch is not a variable of the program", id="a name the program does not declare"),
]


@pytest.mark.parametrize(("condition", "why"), UNREADABLE_CONDITIONS)
def test_a_condition_it_cannot_read_leaves_the_breakpoint_unverified_as_it_is_set(
    debug: Debug, condition: str, why: str
) -> None:
    client = debug(PROGRAM)
    (placed,) = client.set_breakpoints({"line": 6, "condition": condition})
    assert not placed["verified"]
    assert why in placed["message"]


def test_a_condition_that_fails_to_evaluate_stops_and_says_why(debug: Debug) -> None:
    client = debug(PROGRAM, breakpoints=({"line": 6, "condition": "s / (i - 1) > 1"},))
    stop = client.stopped()
    assert stop["reason"] == "breakpoint"
    assert client.values()["i"] == "1"
    assert "2021" in stop["description"]  # division by zero (000:19063)


def test_breakpoints_in_a_file_outside_the_application_are_refused(debug: Debug, tmp_path) -> None:
    client = debug(PROGRAM)
    arguments = {"source": {"path": str(tmp_path / "other.mnt")}, "breakpoints": [{"line": 1}]}
    (placed,) = client.body("setBreakpoints", arguments)["breakpoints"]
    assert not placed["verified"]


def test_breakpoints_in_the_configuration_file_stop_there_before_the_program_runs(debug: Debug, tmp_path) -> None:
    configuration = tmp_path / "program.cfg"
    configuration.write_text("DIM feed\nfeed = 25\n", encoding="utf-8")
    client = debug("DIM twice\ntwice = feed * 2\n", stopOnEntry=True)
    client.stopped()
    assert client.frames()[0]["source"]["path"] == str(configuration.resolve())
    arguments = {"source": {"path": str(configuration)}, "breakpoints": [{"line": 2}]}
    client.body("setBreakpoints", arguments)
    client.step("continue")
    assert client.frames()[0]["source"]["path"] == str(configuration.resolve())
    assert client.line() == 2
    client.set_breakpoints(2)
    client.step("continue")
    assert client.values() == {"feed": "25", "twice": "0"}


TIMED = """\
DIM ticks
TIMEREVENT = 10
PAUSE ticks = 3
END
#TIMER
  ticks = ticks + 1
RETURN
"""


def test_a_breakpoint_on_a_handlers_label_stops_at_each_event_it_serves(debug: Debug) -> None:
    client = debug(TIMED, stopOnEntry=True)
    client.stopped()
    (placed,) = client.body("setFunctionBreakpoints", {"breakpoints": [{"name": "#TIMER"}]})["breakpoints"]
    assert (placed["verified"], placed["line"]) == (True, 6)
    client.step("continue")
    assert [frame["name"] for frame in client.frames()] == ["#TIMER", "program"]
    assert (client.values()["ticks"], client.evaluate("TIME")) == ("0", "10")
    client.step("continue")
    assert (client.values()["ticks"], client.evaluate("TIME")) == ("1", "20")


RESTOCKED = """\
DIM lows
MOVEBUFFERSIZE(0) = 4
MOVEBUFFERLOW(0) = 2
MOVER(0) = 5
MOVER(0) = 5
MOVER(0) = 5
GO(0)
Pause IDLE(0)
End
Event MOVEBUFFERLOW
  lows = lows + 1
End Event
"""


def test_a_breakpoint_on_a_mintmt_event_longer_than_ten_characters_stops_in_its_block(debug: Debug) -> None:
    # Event MOVEBUFFERLOW (004:109-134) comes when the free places rise to the level: three moves leave one of
    # four places free, and the first move's end frees a second (MT-14). The event's name is longer than a
    # label's ten significant characters.
    client = debug(RESTOCKED, dialect="mintmt", drives="enabled", stopOnEntry=True)
    client.stopped()
    (placed,) = client.body("setFunctionBreakpoints", {"breakpoints": [{"name": "MOVEBUFFERLOW"}]})["breakpoints"]
    assert (placed["verified"], placed["line"]) == (True, 11)
    client.step("continue")
    assert (client.line(), client.values()["lows"], client.evaluate("POS(0)")) == (11, "0", "5")


def test_a_label_the_program_lacks_is_an_unverified_breakpoint(debug: Debug) -> None:
    client = debug(TIMED)
    (placed,) = client.body("setFunctionBreakpoints", {"breakpoints": [{"name": "IN3"}]})["breakpoints"]
    assert not placed["verified"] and "no label #IN3" in placed["message"]


REFUSED = """\
DIM x
x = 1
x = (x +
END
#TIMER
RETURN
"""


def test_breakpoints_in_a_program_the_compiler_refuses_say_so(debug: Debug) -> None:
    """Nothing runs where the controller's compiler refuses the file (C2003 for the missing ')'): each
    breakpoint names that error, not "no statement" on a line that has one or "no label" for one it has."""
    client = debug(REFUSED)
    placed = client.set_breakpoints(2)
    functions = client.body("setFunctionBreakpoints", {"breakpoints": [{"name": "TIMER"}]})["breakpoints"]
    for unverified in (*placed, *functions):
        assert not unverified["verified"]
        assert unverified["message"].startswith("does not compile: C2003: PROGRAM")
        assert "[line 3]" in unverified["message"]
    assert client.stopped()["reason"] == "exception"
