"""TRON prints each line's number as the line runs, in square brackets with C or P for its file; TROFF stops it.

The guide: "[P n]" for a program line, "[C n]" for a configuration line, one mark per line executed, and
both keywords work inside a program (000:16922-16926). Its example puts a space after each mark and shows
TRON's own line, a loop's lines again on every pass, and the program's output among the marks
(000:16929-16943). Its last two lines contradict the rule it states ("[P 5]" without the last pass's NEXT,
and "[P 6]" after TROFF): the description is followed (runtime/BEHAVIOUR.md).
"""

from __future__ import annotations

from tests.runtime.running import simulate


def test_the_guides_example_with_its_loop_variable_declared() -> None:
    # the example's program one line down (DIM a first): TRON 2, FOR 3, PRINT 4, NEXT 5, TROFF 6
    source = "DIM a\nTRON\nFOR a = 1 TO 5\nPRINT a\nNEXT\nTROFF\nPRINT 9\n"
    expected = "[P 2] [P 3] [P 4] 1\n" + "".join(f"[P 5] [P 4] {a}\n" for a in range(2, 6)) + "[P 5] [P 6] 9\n"
    assert simulate(source, enable=False).terminal == expected


def test_configuration_lines_are_marked_c_and_the_trace_goes_on_into_the_program() -> None:
    result = simulate("PRINT 1\n", config="TRON\nDIM b = 2\n", enable=False)
    assert result.terminal == "[C 1] [C 2] [P 1] 1\n"


def test_a_statement_waiting_on_later_ticks_is_marked_once() -> None:
    # WAIT = 10 at tick 0 lets the program go on at tick 10 (T-8)
    assert simulate("TRON\nWAIT = 10\nPRINT TIME\n", enable=False).terminal == "[P 1] [P 2] [P 3] 10\n"


def test_a_line_is_marked_once_for_its_statements_and_again_when_a_loop_comes_back_to_it() -> None:
    source = "DIM a\nTRON : FOR a = 1 TO 2 : PRINT a, : NEXT\nTROFF\nPRINT\n"
    assert simulate(source, enable=False).terminal == "[P 2] 1[P 2] 2[P 3] \n"


def test_an_event_handlers_lines_are_marked_and_the_line_it_interrupted_again() -> None:
    # #TIMER runs 10 ms after TIMEREVENT = 10, while PAUSE waits; PAUSE passes when the handler returns
    source = "DIM a\nTRON\nTIMEREVENT = 10 : PAUSE a\nTROFF\nEND\n#TIMER\na = 1\nRETURN\n"
    assert simulate(source, enable=False).terminal == "[P 2] [P 3] [P 7] [P 8] [P 3] [P 4] "


def test_without_tron_nothing_is_marked_and_troff_alone_does_nothing() -> None:
    assert simulate("TROFF\nPRINT 1\n", enable=False).terminal == "1\n"
