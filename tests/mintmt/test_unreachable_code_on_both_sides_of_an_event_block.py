"""Code the main program can never reach is reported on each side of a MintMT Event block, with a fix each.

The controller enters an Event block only for its event; the main flow goes on around it (MT-7), so after an
endless ``Loop`` the lines before the block and the lines after it are both dead, while the block itself is
not. Each stretch is its own W106 whose fix removes it, and ``--fix --unsafe-fixes`` removes both: one report
for the two, whose fix kept the second stretch, was counted as fixable and then left in place.
"""

from __future__ import annotations

import mintlang
from mintlang.fixes import fix_text

SOURCE = """\
Dim n
Loop
  n = n + 1
End Loop
Print "before"
Event Comms1
  n = 0
End Event
Print "after"
"""


def _check(text: str) -> list[mintlang.Diagnostic]:
    return list(mintlang.check_application(text, dialect="mintmt").program)


def test_each_dead_stretch_is_reported_with_its_fix() -> None:
    dead = [(d.code, SOURCE[d.span.start : d.span.end], len(d.fixes)) for d in _check(SOURCE)]
    assert dead == [("W106", 'Print "before"', 1), ("W106", 'Print "after"', 1)]


def test_fixing_removes_both_and_keeps_the_event_block() -> None:
    fixed = fix_text(SOURCE, _check, unsafe=True)
    assert fixed.text == "Dim n\nLoop\n  n = n + 1\nEnd Loop\nEvent Comms1\n  n = 0\nEnd Event\n"
    assert fixed.remaining == ()
