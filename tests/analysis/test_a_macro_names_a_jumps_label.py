"""A macro after GOSUB or GOTO is replaced by its text, as anywhere else in a program.

The guide: where a macro's name is found in the program, its definition replaces it (000:9110-9111),
and macros are substituted when the program is compiled (000:18494). So with ``DEFINE job = work``,
``GOSUB job`` calls ``#work``; with ``DEFINE job = 5`` it is ``GOSUB 5``, a jump to no label, even
beside a ``#job`` (the jump no longer names it). Before, the name after GOSUB and GOTO was never
replaced: the first program was E3004 in ``mint check`` and stopped ``mint-run``, though the editor's
rename and colouring already took the macro as replaced.
"""

from __future__ import annotations

from tests.analysis.checking import ERROR, WARNING, found
from tests.runtime.running import simulate

CALLS_WORK = "DEFINE job = work\nGOSUB job\nGOTO finish\n#work\nPRINT 1\nRETURN\n#finish\nPRINT 2\n"


def test_a_jump_through_a_macro_reaches_the_label_it_stands_for() -> None:
    assert found(CALLS_WORK) == []
    assert simulate(CALLS_WORK).terminal == "1\n2\n"


def test_a_macro_that_is_no_label_name_is_a_jump_to_no_label() -> None:
    program = "DEFINE job = 5\nGOSUB job\nEND\n#job\nRETURN\n"
    # E3004 at the jump; #job is then a subroutine nothing calls (W104)
    assert found(program) == [("E3004", ERROR, 2), ("W104", WARNING, 4)]
