"""The flow rule (``mintlang/analysis/rules/flow.py``): the complete list of diagnostics each small
program gets, as (code, severity, line); line numbers in comments refer to the Mint v4 guide (000_*)."""

from __future__ import annotations

import pytest

from tests.analysis.checking import ERROR, WARNING, found, only


def test_code_after_end_is_unreachable() -> None:
    assert found("PRINT 1\nEND\nPRINT 2\nPRINT 3\n") == [("W106", WARNING, 3)]


def test_a_label_after_end_is_reachable() -> None:
    assert found("GOSUB sub\nEND\n#sub\nPRINT 2\nRETURN\n") == []


def test_main_program_falling_into_a_subroutine_is_2010_as_a_warning_at_the_return() -> None:
    # line 18965: the manual's own example of #2010 RETURN w/o GOSUB
    source = (
        "DIM running\nREM ** Main Program **\nWHILE running\nREM ** Execution code **\nENDW\n"
        'PRINT "Program terminating"\n#ONERROR\nREM ** Error handler code\nRETURN\n'
    )
    assert found(source) == [("E2010", WARNING, 9)]
    assert found(source.replace('terminating"\n', 'terminating"\nEND\n')) == []


def test_a_subroutine_without_return_running_into_the_next_is_a_warning() -> None:
    assert found("GOSUB a\nGOSUB b\nEND\n#a\nPRINT 1\n#b\nPRINT 2\nRETURN\n") == [("W107", WARNING, 6)]


def test_goto_out_of_a_loop_is_a_warning_of_a_stack_overflow_at_run_time() -> None:
    # line 11205: GOTO out of loops or block IFs "will eventually result in a Stack overflow":
    # the controller compiles it, and only repeated jumps overflow, so it is no compile error
    source = "DIM i\nFOR i = 1 TO 10\nGOTO out\nNEXT\n#out\nEND\n"
    assert found(source) == [("W113", WARNING, 3)]


def test_the_goto_warning_names_the_block_it_leaves_once() -> None:
    diagnostic = only("DIM a\nIF a DO\n  GOTO out\nENDIF\n#out\nEND\n", "W113")
    assert diagnostic.message.startswith("GOTO out leaves the IF block of line 2 open")


def test_goto_inside_its_own_loop_is_fine() -> None:
    assert found("DIM i\nFOR i = 1 TO 10\nIF i = 5 THEN GOTO skip\n#skip\nNEXT\n") == []


def test_exit_outside_a_loop_is_error_2003_when_it_runs() -> None:
    # 000:10224-10245: EXIT terminates a FOR, LOOP, REPEAT or WHILE loop; outside one the simulator raises
    # 2003 (NM-8), so the checker reports the same error, as one raised when the line runs
    assert found("PRINT 1\nEXIT\n") == [("E2003", ERROR, 2)]
    assert only("PRINT 1\nEXIT\n", "E2003").at_run_time
    assert found("LOOP\nIF IN7 = 1 THEN EXIT\nENDL\n") == []


def test_exit_inside_if_then_outside_a_loop_is_error_2003() -> None:
    assert found("IF IN1 THEN EXIT\n") == [("E2003", ERROR, 1)]


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        # 000:18939-18941: FOR loop = 1 TO 10 is error 2006 (LOOP is a keyword), yet its NEXT closes it, so
        # the EXIT inside leaves that loop (000:10236-10245) and is no second error
        pytest.param("FOR loop = 1 TO 10\n  IF IN1 THEN EXIT\nNEXT\nEND\n", [("E2006", ERROR, 1)], id="for-loop"),
        # 000:1710-1711: NEXT with the index name after it is an error, yet it still closes its FOR, so an
        # EXIT after it is outside any loop
        pytest.param("DIM i\nFOR i = 1 TO 2\nNEXT i\nEXIT\n", [("E2003", ERROR, 3), ("E2003", ERROR, 4)], id="next-i"),
        # 000:1752-1756: REPEAT .. UNTIL <condition>; an UNTIL whose condition is missing still ends the block,
        # and, its condition unknown, is no endless loop: what follows can run, and an EXIT there is outside it
        pytest.param(
            "DIM i\nREPEAT\n  i = i + 1\nUNTIL\nPRINT i\nEXIT\n", [("E2003", ERROR, 4), ("E2003", ERROR, 6)], id="until"
        ),
    ],
)
def test_a_broken_loop_word_opens_or_closes_its_loop_for_the_flow(source: str, expected: list) -> None:
    assert found(source) == expected


def test_exit_never_leaves_a_callers_loop() -> None:
    # NM-8: a subroutine's EXIT with no loop of its own is an error even when its caller is in a loop
    source = "LOOP\n  GOSUB check\nENDL\n#check\nIF IN1 THEN EXIT\nRETURN\n"
    assert found(source) == [("E2003", ERROR, 5)]


@pytest.mark.parametrize("loop", [("LOOP", "ENDL"), ("WHILE 1", "ENDW"), ("REPEAT", "UNTIL 0")])
def test_a_main_program_ending_in_an_endless_loop_does_not_fall_into_subroutines(loop) -> None:
    opener, closer = loop
    assert found(f"{opener}\nGOSUB s\n{closer}\n#s\nRETURN\n") == []


def test_code_after_an_endless_loop_is_unreachable_unless_an_exit_leaves_it() -> None:
    assert found("LOOP\nGO\nENDL\nPRINT 1\n") == [("W106", WARNING, 4)]
    assert found("LOOP\nIF IN1 THEN EXIT\nENDL\nPRINT 1\n") == []


@pytest.mark.parametrize("last", ["END", "RETURN"])
def test_a_lone_end_or_return_after_the_endless_main_loop_is_not_dead_code(last: str) -> None:
    # line 293: the manual's program structure ends #main with LOOP .. ENDL then RETURN
    assert found(f"GOSUB main\nEND\n#main\nLOOP\nGO\nENDL\n{last}\n") == []
    assert found(f"LOOP\nGO\nENDL\n{last}\nPRINT 1\n") == [("W106", WARNING, 5)]


@pytest.mark.parametrize(
    ("handler", "expected"),
    [
        pytest.param("PRINT ERR\nEND\n\nRETURN\n", [], id="the-guide's-end-then-return"),
        pytest.param("PRINT ERR\nEND\nRETURN\nPRINT 1\n", [("W106", WARNING, 7)], id="more-after-the-return"),
        pytest.param("PRINT ERR\nEND\nPRINT 1\nRETURN\n", [("W106", WARNING, 6)], id="not-a-lone-return"),
        pytest.param("IF ERR DO\nEND\nRETURN\nENDIF\nRETURN\n", [("W106", WARNING, 6)], id="end-inside-a-block"),
    ],
)
def test_a_lone_return_after_a_handlers_own_end_is_not_dead_code(handler: str, expected: list) -> None:
    # 000:4734-4736 and 000:4793-4795: the manual's #ONERROR handlers stop with END and close with RETURN
    assert found("PRINT 1\nEND\n#ONERROR\n" + handler) == expected


def test_an_if_whose_branches_both_return_does_not_run_on() -> None:
    subroutine = "DIM a\nGOSUB one\nGOSUB two\nEND\n#one\nIF a DO\nRETURN\nELSE\na = 2\nRETURN\nENDIF\n"
    assert found(subroutine + "#two\nRETURN\n") == []
    assert found(subroutine + "PRINT 1\n#two\nRETURN\n") == [("W106", WARNING, 12)]
    one_branch = subroutine.replace("ELSE\na = 2\nRETURN\n", "")
    assert found(one_branch + "#two\nRETURN\n") == [("W107", WARNING, 9)]


def test_a_label_only_goto_reaches_is_part_of_the_code_around_it_not_a_subroutine() -> None:
    source = "DIM a\n#start\na = a + 1\nIF a < 3 THEN GOTO start\nGOTO done\nPRINT a\n#done\nEND\n"
    assert found(source) == [("W106", WARNING, 6)]
