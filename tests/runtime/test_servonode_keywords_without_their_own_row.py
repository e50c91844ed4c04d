"""On ServoNode 51 ``mint-run`` judges a keyword whose table prints no ServoNode 51 row by what the
printed rows agree on, as ``mint check`` does.

WAIT is write only in both rows of its table (000:17324, 17332-17333): ``PRINT WAIT`` stops the program
with error 2002 (000:18915-18918), as on MintDrive, instead of as a read mint-run does not simulate.
TIMEREVENT's minimum on ServoNode 51 is 40 ms (000:16807): 20 is error 3 (000:18518-18521).
"""

from __future__ import annotations

from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate


def test_printing_wait_is_error_2002() -> None:
    result = simulate("PRINT WAIT\n", controller="servonode51")
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 2002, 1)


def test_a_timer_event_below_40_ms_is_error_3() -> None:
    result = simulate("TIMEREVENT = 20\n", controller="servonode51")
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 3, 1)
