"""GOTO out of an event handler leaves the handler's return on the controller's stack: the guide names an
interrupt routine first among what GOTO must not jump out of, before loops and block IFs, as eventually
overflowing the stack (GOTO, 000:11199-11215). W113 names the handler as it names each block left.
"""

from __future__ import annotations

import mintlang

RESTART = """\
DIM n = 0
#main
LOOP
  n = n + 1
ENDL
END
#IN1
  IF n > 5 THEN GOTO main
RETURN
"""


def _warnings(source: str) -> list[tuple[int, str]]:
    return [(d.span.start, d.message) for d in mintlang.check(source) if d.code == "W113"]


def test_a_goto_from_an_input_handler_to_the_main_program_is_reported_at_the_goto() -> None:
    assert _warnings(RESTART) == [
        (
            RESTART.index("GOTO main"),
            "GOTO main leaves the event handler #IN1 of line 7 open; "
            "done repeatedly, this overflows the stack (error 2015)",
        )
    ]


def test_the_handler_is_named_before_the_blocks_left_inside_it() -> None:
    source = "LOOP\nENDL\n#ONERROR\n  IF ERR DO\n    GOTO restart\n  ENDIF\nRETURN\n#restart\nEND\n"
    assert [message for _, message in _warnings(source)] == [
        "GOTO restart leaves the event handler #ONERROR of line 3 and the IF block of line 4 open; "
        "done repeatedly, this overflows the stack (error 2015)"
    ]


def test_a_goto_to_a_label_inside_the_handler_stays_in_it() -> None:
    source = "LOOP\nENDL\n#STOP\n#again\n  IF IN.0 THEN GOTO again\nRETURN\n"
    assert _warnings(source) == []


def test_a_goto_out_of_a_subroutine_called_by_gosub_is_not_an_event_handlers() -> None:
    # the guide names interrupt routines, loops and block IFs only (000:11199-11200)
    source = "GOSUB work\n#done\nEND\n#work\n  GOTO done\nRETURN\n"
    assert _warnings(source) == []


def test_a_shared_exit_whose_return_ends_the_handler_is_no_jump_out_of_it() -> None:
    # the RETURN at #common returns from the handler that jumped there: nothing is left on the stack
    source = "LOOP\n  PRINT 1\nENDL\n#common\n  PRINT 2\nRETURN\n#ONERROR\n  GOTO common\n#STOP\n  GOTO common\n"
    assert _warnings(source) == []


def test_a_goto_back_into_an_endless_main_loop_with_no_end_after_it_is_reported() -> None:
    # the handler after the loop is not where the loop's code settles: nothing runs past an endless loop
    source = "DIM n = 0\n#top\nLOOP\n  n = n + 1\nENDL\n#IN1\n  IF n > 5 THEN GOTO top\nRETURN\n"
    assert [start for start, _ in _warnings(source)] == [source.index("GOTO top")]


def test_a_goto_to_code_that_jumps_round_in_a_circle_is_reported() -> None:
    source = "DIM n = 0\n#top\nn = n + 1\nGOTO top\n#IN1\n  GOTO top\nRETURN\n"
    assert [start for start, _ in _warnings(source)] == [source.rindex("GOTO top")]


def test_a_shared_exit_reached_through_another_goto_still_ends_the_handler() -> None:
    source = "LOOP\nENDL\n#exit\n  GOTO common\n#common\n  PRINT 2\nRETURN\n#ONERROR\n  GOTO exit\n"
    assert _warnings(source) == []
