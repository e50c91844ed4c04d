"""A GOTO out of blocks leaves every one of them on the controller's stack (GOTO, 000:11199-11215), so its
one warning (W113, at the GOTO: the statement to change) names each block it leaves, outermost first,
with the line it opens on; a block the label is inside is not left.
"""

from __future__ import annotations

import mintlang

NESTED = """\
LOOP
  DIM i
  FOR i = 1 TO 3
    IF IN1 DO
      GOTO out
    ENDIF
  NEXT
ENDL
#out
END
"""


def _messages(source: str) -> list[str]:
    return [d.message for d in mintlang.check(source) if d.code == "W113"]


def test_a_goto_out_of_three_blocks_names_all_three_in_one_warning() -> None:
    assert _messages(NESTED) == [
        "GOTO out leaves the LOOP block of line 1, the FOR block of line 3 and the IF block of line 4 open; "
        "done repeatedly, this overflows the stack (error 2015)"
    ]


def test_two_blocks_left_are_named_with_and() -> None:
    source = "DIM i\nFOR i = 1 TO 3\n  IF IN1 DO\n    GOTO out\n  ENDIF\nNEXT\n#out\nEND\n"
    assert _messages(source) == [
        "GOTO out leaves the FOR block of line 2 and the IF block of line 3 open; "
        "done repeatedly, this overflows the stack (error 2015)"
    ]


def test_the_block_holding_the_label_is_not_named() -> None:
    # the manual's own example (000:11202-11213): #abortLoop is inside the LOOP, so only the IF block is left
    source = "LOOP\n  IF IN1 DO\n    IF IN2 THEN GOTO abortLoop\n  ENDIF\n  #abortLoop\nENDL\n"
    assert _messages(source) == [
        "GOTO abortLoop leaves the IF block of line 2 open; done repeatedly, this overflows the stack (error 2015)"
    ]
