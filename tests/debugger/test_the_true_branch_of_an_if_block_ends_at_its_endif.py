"""An IF .. DO block's true branch runs up to its ELSE, the false branch from after it (000:1601-1605): the ELSE
line starts the false branch for its reader, so the jump that ends the true branch is shown, stepped and broken at
on the ENDIF line, where either branch leaves the block, as coverage counts it.
"""

from __future__ import annotations

from tests.debugger.conftest import Debug

BRANCHES = """\
DIM i
DIM s
FOR i = 1 TO 2
  IF i = 1 DO
    s = s + 10
  ELSE
    s = s + 1
  ENDIF
NEXT
PRINT s
"""


def test_next_from_the_true_branch_goes_to_the_endif_not_the_else(debug: Debug) -> None:
    client = debug(BRANCHES, breakpoints=(5,))
    client.stopped()
    client.set_breakpoints()
    client.step("next")
    assert (client.line(), client.frames()[0]["column"], client.values()["s"]) == (8, 3, "10")
    client.step("next")
    assert client.line() == 9


def test_a_breakpoint_on_the_endif_stops_after_either_branch(debug: Debug) -> None:
    client = debug(BRANCHES, breakpoints=(8,))
    client.stopped()
    assert (client.line(), client.values()["i"], client.values()["s"]) == (8, "1", "10")  # after the true branch
    client.step("continue")
    assert (client.line(), client.values()["i"], client.values()["s"]) == (8, "2", "11")  # after the false branch


def test_a_breakpoint_on_the_else_stops_as_the_false_branch_starts(debug: Debug) -> None:
    client = debug(BRANCHES, breakpoints=(6,))
    client.stopped()
    assert (client.line(), client.values()["i"], client.values()["s"]) == (7, "2", "10")
    placed = client.set_breakpoints(6)
    assert (placed[0]["verified"], placed[0]["line"]) == (True, 7)
