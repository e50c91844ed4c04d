"""The call stack names each frame by what opened it: the program's own frame is the program, a GOSUB's frame
the subroutine it called, however many labels a GOTO jumps to inside them.

GOSUB calls the subroutine its label starts (000:1841-1853); GOTO only branches to a label
(000:11187-11188), so a label a GOTO names opens no frame, in the program or in a subroutine.
"""

from __future__ import annotations

from tests.debugger.conftest import Debug

LOOPS = """\
DIM n
#again
  n = n + 1
  IF n < 3 THEN GOTO again
GOSUB count
END
#count
  n = n - 1
#down
  n = n - 1
  IF n > 0 THEN GOTO down
RETURN
"""


def test_the_program_after_a_goto_label_is_still_the_program(debug: Debug) -> None:
    client = debug(LOOPS, breakpoints=(3,))
    client.stopped()
    assert [(frame["name"], frame["line"]) for frame in client.frames()] == [("program", 3)]


def test_a_subroutine_past_its_own_goto_label_is_the_subroutine_called_from_the_program(debug: Debug) -> None:
    client = debug(LOOPS, breakpoints=(12,))
    client.stopped()
    frames = [(frame["name"], frame["line"]) for frame in client.frames()]
    assert frames == [("#count", 12), ("program", 5)]  # the GOSUB on line 5, in the program's frame
