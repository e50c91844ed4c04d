"""Stepping back and reverse-continue land where a forward run stood, with the same state.

Going back restores a checkpoint taken before the earlier point and runs on
to it (``runtime/debugger/checkpoints.py``); these tests step forward through a
program recording each stop, then walk back and compare every stop with the
forward one. The values are worked out by hand from the program.
"""

from __future__ import annotations

from tests.debugger.conftest import Debug

LOOP = """\
DIM a
DIM b = 1
FOR a = 1 TO 2
  b = b * 3
NEXT
PRINT b
"""

# Each stop of ``LOOP`` stepping forward from its entry: (line, a, b) before the line runs.
FORWARD = [(1, "0", "0"), (2, "0", "0"), (3, "0", "1"), (4, "1", "1"), (5, "1", "3"), (4, "2", "3"), (5, "2", "9")]
FORWARD += [(6, "2", "9")]


def _state(client) -> tuple[int, str, str]:
    values = client.values()
    return client.line(), values["a"], values["b"]


def test_stepping_forward_stops_before_each_statement_in_turn(debug: Debug) -> None:
    client = debug(LOOP, stopOnEntry=True)
    assert client.stopped()["reason"] == "entry"
    seen = [_state(client)]
    for _ in FORWARD[1:]:
        assert client.step("next")["reason"] == "step"
        seen.append(_state(client))
    assert seen == FORWARD


def test_stepping_back_from_the_last_statement_revisits_every_stop_with_its_state(debug: Debug) -> None:
    client = debug(LOOP, breakpoints=(6,))
    assert client.stopped()["reason"] == "breakpoint"
    seen = [_state(client)]
    for _ in FORWARD[:-1]:
        assert client.step("stepBack")["reason"] == "step"
        seen.append(_state(client))
    assert seen == FORWARD[::-1]


def test_stepping_forward_again_after_stepping_back_prints_nothing_twice(debug: Debug) -> None:
    client = debug(LOOP, breakpoints=(6,))
    client.stopped()
    client.step("stepBack")
    client.step("stepBack")
    client.set_breakpoints()
    client.body("continue", {"threadId": 1})
    client.event("terminated")
    assert client.output().split() == ["9"]


def test_reverse_continue_goes_back_to_the_previous_hit_of_a_breakpoint(debug: Debug) -> None:
    client = debug(LOOP, breakpoints=(4, 6))
    client.stopped()
    assert _state(client) == (4, "1", "1")
    client.step("continue")
    client.step("continue")
    assert _state(client) == (6, "2", "9")
    assert client.step("reverseContinue")["reason"] == "breakpoint"
    assert _state(client) == (4, "2", "3")
    client.step("reverseContinue")
    assert _state(client) == (4, "1", "1")


def test_reverse_continue_finds_the_hits_of_a_breakpoint_set_after_they_were_passed(debug: Debug) -> None:
    client = debug(LOOP, breakpoints=(6,))
    client.stopped()
    client.set_breakpoints(4, 6)
    client.step("reverseContinue")
    assert _state(client) == (4, "2", "3")
    client.set_breakpoints({"line": 4, "condition": "a = 1"})
    client.step("reverseContinue")
    assert _state(client) == (4, "1", "1")


def test_reverse_continue_with_no_earlier_hit_stops_at_the_start(debug: Debug) -> None:
    client = debug(LOOP, breakpoints=(4,))
    client.stopped()
    assert client.step("reverseContinue")["reason"] == "entry"
    assert _state(client) == (1, "0", "0")


SUBROUTINE = """\
DIM total
DIM i
FOR i = 1 TO 2
  GOSUB add
NEXT
PRINT total
END
#add
  total = total + i
RETURN
"""


def test_stepping_back_over_a_gosub_skips_the_subroutine_as_next_does(debug: Debug) -> None:
    client = debug(SUBROUTINE, breakpoints=(5,))
    client.stopped()
    assert (client.line(), client.values()["total"]) == (5, "1")
    client.step("stepBack")
    assert (client.line(), client.values()["total"]) == (4, "0")


def test_stepping_back_inside_a_subroutine_stays_in_it_then_leaves_for_the_gosub(debug: Debug) -> None:
    client = debug(SUBROUTINE, breakpoints=(10,))
    client.stopped()
    assert [frame["name"] for frame in client.frames()] == ["#add", "program"]
    client.step("stepBack")
    assert client.line() == 9
    client.step("stepBack")
    assert client.line() == 4
    assert [frame["name"] for frame in client.frames()] == ["program"]


def test_a_value_set_while_paused_holds_going_forward_and_is_undone_going_back_before_it(debug: Debug) -> None:
    client = debug(LOOP, breakpoints=(5,))
    client.stopped()
    client.body("setVariable", {"variablesReference": client.scope("Variables"), "name": "b", "value": "100"})
    client.step("next")
    assert client.values()["b"] == "100"
    client.step("stepBack")
    assert client.values()["b"] == "100"  # back to the point it was set at: set again there
    client.step("stepBack")
    assert client.values()["b"] == "1"  # before it: never set
    client.set_breakpoints()
    client.body("continue", {"threadId": 1})
    client.event("terminated")
    assert client.output().split() == ["9"]
