"""On ServoNode 51 ``mint check`` judges a keyword whose table prints no ServoNode 51 row by what the
printed rows agree on.

WAIT is write only in both rows of its table (000:17324, 17332-17333), so reading it is error 2002
(000:18915-18918); TIMEREVENT's minimum on MintDrive and ServoNode 51 is 40 ms (000:16787, 16807),
so 20 is error 3 (000:18518-18521), while 40 is taken.
"""

from __future__ import annotations

import mintlang


def _codes(source: str) -> list[str]:
    return [d.code for d in mintlang.check(source, controller="servonode51")]


def test_reading_wait_is_error_2002() -> None:
    assert _codes("DIM x\nx = WAIT\n") == ["E2002"]


def test_a_timer_event_below_40_ms_is_error_3() -> None:
    assert _codes("TIMEREVENT = 20\n") == ["E0003"]


def test_a_timer_event_of_40_ms_is_taken() -> None:
    assert _codes("TIMEREVENT = 40\n") == []
