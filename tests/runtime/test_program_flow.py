"""The interpreter runs Mint's statements and blocks as the v4 guide describes them."""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate


def printed(source: str, **options: object) -> str:
    result = simulate(source, **options)  # type: ignore[arg-type]
    assert result.stop.reason is StopReason.END, result.stop
    return result.terminal


def test_a_for_loop_leaves_its_variable_at_the_upper_limit() -> None:
    # NM-9: unlike BASIC, the variable equals the limit when the loop ends
    assert printed("DIM a\nFOR a = 1 TO 5\nNEXT\nPRINT a\n") == "5\n"


def test_a_for_loop_whose_start_is_past_its_limit_never_runs_its_body() -> None:
    assert printed('DIM a\nFOR a = 7 TO 5\nPRINT "body"\nNEXT\nPRINT a\n') == "7\n"


def test_a_for_loop_counts_down_with_a_negative_step() -> None:
    assert printed("DIM a\nFOR a = 3 TO 1 STEP -1\nPRINT a;\nNEXT\nPRINT\n") == "3       2       1       \n"


def test_nested_loops_and_exit_leave_only_the_innermost_loop() -> None:
    source = """DIM i
DIM j
FOR i = 1 TO 3
  LOOP
    j = j + 1
    IF j > 5 THEN EXIT
  ENDL
NEXT
PRINT i, " ", j
"""
    assert printed(source) == "3 8\n"


def test_repeat_runs_at_least_once_and_while_may_never_run() -> None:
    source = """DIM n = 10
REPEAT
  n = n + 1
UNTIL n > 0
WHILE n < 0
  n = 0
ENDW
PRINT n
"""
    assert printed(source) == "11\n"


def test_if_do_else_takes_one_branch() -> None:
    source = """DIM x = 2
IF x = 1 DO
  PRINT "one"
ELSE
  PRINT "not one"
ENDIF
IF x = 2 THEN PRINT "two" : PRINT "still two"
IF x = 3 THEN PRINT "three" : PRINT "never"
"""
    assert printed(source) == "not one\ntwo\nstill two\n"


def test_gosub_returns_after_the_call_and_goto_jumps() -> None:
    source = """GOSUB greet
GOTO finish
PRINT "skipped"
#finish
PRINT "end"
END
#greet
PRINT "hello"
RETURN
"""
    assert printed(source) == "hello\nend\n"


def test_arrays_are_one_based_and_filled_from_their_dim() -> None:
    source = "DIM table(4) = 1, 2;\nPRINT table(1), table(2), table(3), table(4)\n"
    assert printed(source) == "1222\n"


def test_an_index_outside_the_array_is_error_2016_on_its_line() -> None:
    result = simulate("DIM table(3)\nDIM i = 4\nDIM x\nx = table(i)\n")
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 2016, 4)
    assert "R2016" in result.stop.message and "[line 4]" in result.stop.message


def test_the_configuration_runs_first_and_its_end_moves_on_to_the_program() -> None:
    config = 'DIM shared = 7\nPRINT "config"\nEND\nPRINT "never"\n'
    assert printed('PRINT "program ", shared\n', config=config) == "config\nprogram 7\n"


def test_recursion_beyond_the_gosub_limit_is_a_stack_overflow() -> None:
    result = simulate("#down\nGOSUB down\n")
    assert (result.stop.reason, result.err) == (StopReason.ERROR, 2015)


def test_a_return_without_gosub_is_error_2010() -> None:
    result = simulate('PRINT "x"\nRETURN\n')
    assert (result.err, result.erl) == (2010, 2)


ONERROR_SHOWS_ERR_ERL = '\nPRINT "resumed"\nEND\n#ONERROR\nPRINT "error ", ERR, " on line ", ERL\nRETURN\n'


def test_onerror_sees_err_erl_and_resumes_after_a_failing_system_statement() -> None:
    # axis 12 is invalid (000:4616-4618): the system error 2, after which RETURN resumes (EV-19 RC)
    assert printed("DIM a = 0\na = POS.12" + ONERROR_SHOWS_ERR_ERL) == "error 2 on line 2\nresumed\n"


def test_onerror_sees_an_interpreter_error_and_its_return_ends_the_program() -> None:
    # 000:4614-4619: an interpreter error (2021, 000:19063) calls #ONERROR, then terminates the program
    result = simulate("DIM a = 0\na = 1 / a" + ONERROR_SHOWS_ERR_ERL)
    assert (result.stop.reason, result.stop.line, result.err, result.erl) == (StopReason.ERROR, 2, 2021, 2)
    assert result.terminal == "error 2021 on line 2\nR2021: PROGRAM Divide by zero [line 2]\n"


def test_an_error_in_a_keyword_names_its_axis_in_erraxis() -> None:
    # the manual's example: MOVER.8 = 20 on a 4-axis controller gives ERR 2, ERRAXIS 8 [000:9949-9956]
    source = 'DIM a\na = 8\nMOVER.a = 20\nEND\n#ONERROR\nPRINT ERR, " ", ERL, " ", ERRAXIS\nRETURN\n'
    assert printed(source, controller="nextmove-bx") == "2 3 8\n"


def test_a_compile_error_stops_the_run_before_the_first_statement() -> None:
    result = simulate('PRINT "never"\nx = 1\n')
    assert result.stop.reason is StopReason.ERROR
    assert result.terminal == "C3001: PROGRAM Variable undefined, use DIM [line 2]\n"  # only the compiler's message
    assert result.stop.message.startswith("C3001") and result.stop.line == 2


def test_wait_suspends_for_its_milliseconds() -> None:
    assert printed("PRINT TIME\nWAIT = 250\nPRINT TIME\n") == "0\n250\n"


def test_input_reads_a_typed_number_and_inkey_a_key() -> None:
    source = """REM @sim key "42\\r" at 100
REM @sim key "q" at 300
DIM n
INPUT "n? ", n
PRINT n * 2
PAUSE INKEY = 'Q'
PRINT "quit at ", TIME
"""
    assert printed(source) == "n? 42\n84\nquit at 300\n"


def test_a_program_blocked_for_ever_is_a_deadlock() -> None:
    # three moves into a two-move buffer and no GO: the third waits for ever [000:2962-2969]
    result = simulate('MOVER.0 = 10\nMOVER.0 = 10\nMOVER.0 = 10\nPRINT "never"\n')
    assert (result.stop.reason, result.stop.line) == (StopReason.DEADLOCK, 3)


def test_a_busy_loop_stops_at_until_ms_and_says_where() -> None:
    result = simulate("DIM n\nLOOP\n  n = n + 1\nENDL\n", until_ms=50)
    assert result.stop.reason is StopReason.UNTIL and result.stop.time_ms == 50
    assert result.stop.line in (3, 4)


@pytest.mark.parametrize(
    ("statement", "shown"),
    [
        ("PRINT 1 + 0.555", "1.555"),
        ("PRINT HEX 74", "4A"),
        ("PRINT BIN 27", "11011"),
        ("PRINT -123.5 USING -5, 1", "-00123.5"),
    ],
)
def test_print_formats_numbers_as_the_manual_shows(statement: str, shown: str) -> None:
    assert printed(statement + "\n") == shown + "\n"


def test_input_asks_again_when_the_entry_is_not_a_number() -> None:
    source = 'REM @sim key "abc\\r7\\r" at 10\nDIM n\nINPUT "n? ", n\nPRINT n\n'
    assert printed(source) == "n? abc\nn? 7\n7\n"


def test_exit_cannot_leave_the_loop_of_a_subroutines_caller() -> None:
    # NM-8: EXIT leaves the innermost loop of its own subroutine; a caller's loop is out of its reach
    source = """DIM i
FOR i = 1 TO 3
  GOSUB sub
NEXT
END
#sub
EXIT
RETURN
"""
    result = simulate(source)
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 2003, 7)


ONERROR_REPORTS = '\nEND\n#ONERROR\nPRINT "error ", ERR\nRETURN\n'


@pytest.mark.parametrize(
    ("construct", "shown"),
    [
        ('IF POS.12 > 0 THEN PRINT "guarded"\nPRINT "after"', "error 2\nafter\n"),
        ('IF POS.12 > 0 DO\n  PRINT "guarded"\nELSE\n  PRINT "else"\nENDIF\nPRINT "after"', "error 2\nafter\n"),
        ('WHILE POS.12 > 0\n  PRINT "guarded"\nENDW\nPRINT "after"', "error 2\nafter\n"),
        ('FOR i = 1 TO POS.12\n  PRINT "guarded"\nNEXT\nPRINT "after"', "error 2\nafter\n"),
        ('REPEAT\n  PRINT "body"\nUNTIL POS.12\nPRINT "after"', "body\nerror 2\nafter\n"),
    ],
)
def test_onerror_returns_after_a_failing_block_statement_never_into_its_block(construct: str, shown: str) -> None:
    # EV-19 RC: the statement after the failing one is the one after the whole construct; reading axis 12 is
    # the system error 2 (000:4616-4618), which RETURN resumes after
    assert printed("DIM i\n" + construct + ONERROR_REPORTS) == shown


def test_an_until_that_fails_leaves_its_loop_so_the_enclosing_for_goes_on() -> None:
    source = "DIM k\nFOR k = 1 TO 60\n  REPEAT\n  UNTIL POS.12\nNEXT\nPRINT k\nEND\n#ONERROR\nRETURN\n"
    assert printed(source) == "60\n"


def test_a_subroutine_reentered_from_an_event_keeps_its_own_loop_limits() -> None:
    # the timer calls count while the program is inside count's FOR: the call's FOR 1 TO 1 does not replace
    # the program's FOR 1 TO 3, which goes on from the clobbered i = 1 (body runs: i = 1, 2, 2, 3, and one call)
    source = """DIM i
DIM runs
DIM upto = 3
TIMEREVENT = 10
GOSUB count
PRINT runs
END
#count
FOR i = 1 TO upto
  WAIT = 8
  runs = runs + 1
NEXT
RETURN
#TIMER
TIMEREVENT = 0
upto = 1
GOSUB count
RETURN
"""
    assert printed(source) == "5\n"


def test_input_using_truncates_the_decimals_and_takes_a_sign_only_with_a_negative_width() -> None:
    # 000:12223-12229: <frac> places, the rest truncated; signed numbers only when <int> is negative,
    # the '-' key ignored otherwise (000:12239): -3 typed into USING 5,1 is 3
    source = 'REM @sim key "12.345\\r-3\\r" at 5\nDIM a\nDIM b\nINPUT a USING -5,2\nINPUT b USING 5,1\n'
    assert printed(source + 'PRINT a, " ", b\n') == "12.345\n-3\n12.34 3\n"
