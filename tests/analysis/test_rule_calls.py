"""The calls rule (``mintlang/analysis/rules/calls.py``): the complete list of diagnostics each small
program gets, as (code, severity, line); line numbers in comments refer to the Mint v4 guide (000_*)."""

from __future__ import annotations

from tests.analysis.checking import WARNING, covered, found, only


def _chain(levels: int) -> str:
    """A main program whose GOSUB starts ``levels`` nested calls."""
    routines = "".join(f"#s{i}\nGOSUB s{i + 1}\nRETURN\n" for i in range(levels - 1))
    return f"GOSUB s0\nEND\n{routines}#s{levels - 1}\nRETURN\n"


def test_a_subroutine_that_calls_itself_nests_deeper_with_every_call() -> None:
    # every GOSUB nests a level until its RETURN; 100 levels at most (3.9, GOSUB notes)
    assert found("GOSUB count\nEND\n#count\nGOSUB count\nRETURN\n") == [("W115", WARNING, 4)]
    source = "GOSUB a\nEND\n#a\nGOSUB b\nRETURN\n#b\nIF 1 THEN GOSUB a\nRETURN\n"
    assert found(source) == [("W115", WARNING, 7)]
    assert covered(source, only(source, "W115")) == "GOSUB a"


def test_calls_nested_deeper_than_the_controller_allows_are_a_warning_at_the_first_gosub() -> None:
    assert found(_chain(100)) == []
    assert found(_chain(101)) == [("W116", WARNING, 1)]
    # NextMove PC allows 50 levels (and 100 labels)
    assert [code for code, _, _ in found(_chain(51), controller="nextmove-pc")] == ["W116"]
    assert found(_chain(50), controller="nextmove-pc") == []


def test_an_event_handler_starts_its_own_chain_and_goto_loops_nest_nothing() -> None:
    handler = "END\n#IN1\nGOSUB s0\nRETURN\n" + _chain(101).removeprefix("GOSUB s0\nEND\n")
    assert ("W116", WARNING, 3) in found(handler)
    assert found("#top\nPRINT 1\nGOTO top\n") == []
