"""Errors the controller raises when a line runs reach #ONERROR, even those mint check finds beforehand.

Only the compiler's errors (syntax, undeclared names, mismatched blocks,
labels, limits) stop a program before it starts (000:4564-4570, 4611-4615);
system and interpreter errors call #ONERROR if it is defined (000:4616-4619).
After a system error the program can go on (EV-19 of the runtime spec); an
interpreter error ends it when the handler returns (000:4614-4615).
"""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate

HANDLER = 'END\n#ONERROR\nPRINT ERR, " ", ERL, " ", ERRAXIS\nRETURN\n'


def test_the_errors_example_an_axis_the_controller_lacks_is_error_2_on_its_line() -> None:
    # 000:9949-9956: MOVER.8 = 20 on line 2 gives ERR 2, ERL 2 and ERRAXIS 8 (NextMove BX: axes 0 to 7)
    result = simulate("MOVER.0 = 10\nMOVER.8 = 20\nGO[0,7]\n" + HANDLER)
    assert result.terminal.startswith("2 2 8\n")


def test_an_index_outside_its_array_is_error_2016_when_the_line_runs() -> None:
    # 000:19040-19046: indices of DIM t(3) are 1 to 3; after RETURN the program ends there (000:4614-4615)
    result = simulate('DIM t(3)\nt(4) = 1\nPRINT "after"\n' + HANDLER)
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 2016, 2)
    assert result.terminal == "2016 2 -1\nR2016: PROGRAM Invalid index [line 2]\n"


def test_a_constant_out_of_range_is_error_3_when_the_line_runs() -> None:
    # 000:4600-4606: SCALE = -3 is printed as R0003, a run-time error; ERRAXIS names the axis
    result = simulate('PRINT "before"\nSCALE.0 = -3\nPRINT "after"\n' + HANDLER)
    assert result.terminal == "before\n3 2 0\nafter\n"


def test_without_a_handler_the_error_stops_the_program_at_its_line() -> None:
    # 000:4579-4590: with no #ONERROR the controller prints the error with its line
    result = simulate('PRINT "before"\nDIM t(2)\nt(0) = 1\nPRINT "never"\n')
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 2016, 3)
    assert result.terminal == "before\nR2016: PROGRAM Invalid index [line 3]\n"


def test_a_macro_left_in_another_macros_text_is_a_syntax_error_when_its_line_runs() -> None:
    # 000:1549-1553: "A syntax error will result at run time"
    source = 'DEFINE one = 1\nDEFINE show = PRINT one\nPRINT "before"\nshow\nPRINT "after"\n'
    result = simulate(source)
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 2003, 4)
    assert result.terminal == "before\nR2003: PROGRAM Syntax error [line 4]\n"


def test_a_write_to_a_read_only_keyword_is_error_2000_when_its_line_runs() -> None:
    # 000:18905-18908: CAMINDEX = 4 is the manual's example of 2000
    result = simulate('PRINT "before"\nCAMINDEX = 4\nPRINT "after"\n' + HANDLER)
    assert result.terminal == "before\n2000 2 -1\nR2000: PROGRAM Read only or Command [line 2]\n"


def test_a_keyword_alone_is_error_2005_when_its_line_runs() -> None:
    # 000:18930-18934: SPEED : REM ... is the manual's example of 2005
    result = simulate("SPEED : REM ** Axis Slew Speed **\n")
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 2005, 1)


@pytest.mark.parametrize("statement", ["SPEED.0 =", "MOVEA =", "MOVER = ,", "JOG =", "OUT =", "COMMS(1) ="])
def test_a_keyword_given_no_value_after_its_equals_is_error_2005_when_its_line_runs(statement: str) -> None:
    # 000:18930-18934: the keyword is neither read nor given a value; every place of the list is empty
    result = simulate(f'PRINT "before"\n{statement}\nPRINT "never"\n')
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 2005, 2)
    assert result.terminal == "before\nR2005: PROGRAM No expression [line 2]\n"


def test_a_skipped_place_beside_a_value_is_no_error() -> None:
    # 000:632-641: SPEED = ,,20 writes axis 2 only
    assert simulate("SPEED = ,,20\nPRINT SPEED.2\n").terminal == "20\n"


def test_an_axis_named_twice_in_a_write_is_error_2018() -> None:
    # 000:19053-19058: SPEED [2,2,3] = 5000; is the manual's example of 2018
    result = simulate("SPEED [2,2,3] = 5000;\n")
    assert (result.err, result.erl, result.terminal) == (2018, 1, "R2018: PROGRAM Axis set more than once [line 1]\n")


def test_a_keyword_the_simulator_does_not_model_stops_only_the_run_that_reaches_it() -> None:
    assert simulate('DIM a\nIF a DO\n  PRINT AUXENCODERSCALE.0\nENDIF\nPRINT "ran"\n').terminal == "ran\n"
    stopped = simulate("PRINT AUXENCODERSCALE.0\n")
    assert (stopped.stop.reason, stopped.stop.line) == (StopReason.ERROR, 1)
    assert "not simulated" in stopped.stop.message


def test_a_keyword_the_controller_does_not_have_is_error_17_when_its_line_runs() -> None:
    # 000:18570-18575: a keyword not supported on the controller; EVENTPENDING is NextMove only (000:10116-10125)
    result = simulate('PRINT "a"\nEVENTPENDING = 0\nPRINT "b"\n' + HANDLER, controller="mintdrive")
    assert result.terminal == "a\n17 2 -1\nb\n"


def test_values_outside_a_keywords_range_are_error_3() -> None:
    # the attributes tables: WAIT 2 to 16777215 on NextMove (000:17330), TIMEREVENT 40 and up on MintDrive (000:16786)
    assert simulate("WAIT = 1\n" + HANDLER).terminal == "3 1 -1\n"
    assert simulate("TIMEREVENT = 25\n" + HANDLER, controller="mintdrive").terminal == "3 1 -1\n"
    assert simulate("EVENTDISABLE = 600\n" + HANDLER).terminal == "3 1 -1\n"


def test_more_axes_than_the_controller_has_is_error_2017() -> None:
    # 000:19047-19052: SPEED[0,1,3] = 5000; is invalid on a single axis controller
    result = simulate("SPEED[0,1,3] = 5000;\n", controller="mintdrive")
    assert (result.err, result.erl) == (2017, 1)
