"""A GOTO from the main program into an event handler's code is error 2010, reported at the GOTO.

No GOSUB and no event called the handler, so the RETURN that ends it finds nothing to return to: "RETURN
has been found without a GOSUB having being executed" (000:18965-18967). The check knows it before the
run: the GOTO's label lies between the handler's label and its RETURN. A subroutine called by GOSUB
(000:11146-11158) is entered the same way. MintMT's ``End Event`` returns from its block as v4's RETURN
returns from a handler (the project's MT-7), so a ``Goto`` into an ``Event`` block from outside is the same.
"""

from __future__ import annotations

import mintlang
from mintlang import Diagnostic

INTO_A_HANDLER = """\
DIM n = 0
IF IN.0 THEN GOTO reply
END
#COMMS1
  n = COMMS(1)
#reply
  PRINT n
RETURN
"""


def _errors_2010(source: str, dialect: str = "v4") -> list[Diagnostic]:
    return [d for d in mintlang.check(source, dialect=dialect) if d.code == "E2010"]


def test_a_goto_into_a_handlers_body_is_reported_at_the_goto() -> None:
    (error,) = _errors_2010(INTO_A_HANDLER)
    assert error.severity.value == "error"
    assert error.span.start == INTO_A_HANDLER.index("GOTO reply")
    assert error.message == (
        "RETURN w/o GOSUB: GOTO reply jumps from the main program into the event handler #COMMS1 of line 4, "
        "whose RETURN then has no GOSUB to return to"
    )


def test_a_goto_to_the_handlers_own_label_is_reported_too() -> None:
    source = "GOTO IN1\nEND\n#IN1\n  PRINT 1\nRETURN\n"
    (error,) = _errors_2010(source)
    assert "GOTO IN1 jumps from the main program into the event handler #IN1 of line 3" in error.message


def test_a_goto_into_a_subroutine_called_by_gosub_is_reported_as_a_subroutine() -> None:
    source = "GOSUB work\nGOTO work\nEND\n#work\n  PRINT 1\nRETURN\n"
    (error,) = _errors_2010(source)
    assert "GOTO work jumps from the main program into the subroutine #work of line 4" in error.message


def test_a_goto_to_code_that_ends_the_program_before_the_return_is_not_reported() -> None:
    source = "GOTO halt\nEND\n#IN1\n  PRINT 1\n#halt\n  END\nRETURN\n"
    assert _errors_2010(source) == []


def test_a_goto_inside_the_handler_is_not_reported() -> None:
    source = "LOOP\nENDL\n#IN1\n#again\n  IF IN.1 THEN GOTO again\nRETURN\n"
    assert _errors_2010(source) == []


def test_a_goto_from_one_handler_into_another_is_not_the_main_programs() -> None:
    # the second handler's RETURN returns from the first one's event (test_goto_out_of_an_event_handler)
    source = "LOOP\nENDL\n#IN1\n  GOTO common\n#IN2\n#common\n  PRINT 2\nRETURN\n"
    assert _errors_2010(source) == []


def test_a_mintmt_goto_into_an_event_block_is_reported() -> None:
    source = "Dim n = 0\nGoto reply\nEnd\nEvent Comms1\n  n = 1\n#reply\n  Print n\nEnd Event\n"
    (error,) = _errors_2010(source, "mintmt")
    assert error.span.start == source.index("Goto reply")
    assert error.message == (
        "RETURN w/o GOSUB: Goto reply jumps from the main program into the Event block of line 4, "
        "whose End Event then has no GOSUB to return to"
    )
