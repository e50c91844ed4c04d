"""SOFTLIMITMODE 4, smart mode (000:16057-16074): where the conformance cases do not reach.

The cases in ``tests/conformance/motion/softlimit_smart_*`` show the moves it stops; here are the
edges: a move that starts on its limit, a motion smart mode does not cover, and a controller other
than a NextMove. ``simulate`` also runs each program tick by tick and requires the same result.
"""

from __future__ import annotations

from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate

HANDLER = "END\n#ONERROR\ne = AXISERROR.0 : t = TIME : p = POS.0\nRETURN\n"


def test_a_move_that_starts_on_its_limit_stops_at_once_and_calls_the_handler() -> None:
    """Nothing to ramp down: the limit is the end point from the first profiler tick (2 ms) on."""
    source = (
        "DIM e\nDIM t\nDIM p\nSOFTLIMITFORWARD.0 = 0 : SOFTLIMITMODE.0 = 4\n"
        'MOVEA.0 = 100 : GO.0\nPAUSE e <> 0\nWAIT = 100\nPRINT POS.0, " ", IDLE.0\n' + HANDLER
    )
    result = simulate(source)
    assert result.stop.reason is StopReason.END
    assert result.terminal == "0 0\n"
    assert result.axes[0].axiserror == 8


def test_a_limit_passed_by_a_motion_smart_mode_does_not_cover_crash_stops_the_axis() -> None:
    """FOLLOW is not among the moves smart mode stops (000:16073-16074): the axis crash-stops, as mode 2
    (the choice mode 3 makes where it cannot ramp, 000:16091-16093), and its drive stays enabled. Axis 1
    moves at 1000 counts/s from 0; axis 0 follows it at ratio 1 and is stopped just past 500."""
    source = (
        "DIM e\nDIM t\nDIM p\nSOFTLIMITFORWARD.0 = 500 : SOFTLIMITMODE.0 = 4\n"
        "MASTERSOURCE.0 = _msPOS : MASTERCHANNEL.0 = 1 : FOLLOW.0 = 1\n"
        "SPEED.1 = 1000 : ACCEL.1 = 1000000 : DECEL.1 = 1000000\n"
        'MOVEA.1 = 1000 : GO.1\nPAUSE e <> 0\nPRINT e, " ", AXISMODE.0, " ", DRIVEENABLE.0, " ", p\n'
        "END\n#ONERROR\ne = AXISERROR.0 : p = POS.0 : CANCEL.0\nRETURN\n"
    )
    result = simulate(source)
    assert result.stop.reason is StopReason.END
    assert result.terminal == "8 0 1 501\n"


def test_smart_mode_off_a_nextmove_stops_the_run_as_not_simulated() -> None:
    """The guide gives mode 4 for NextMove only (000:16068) and says nothing of it on a MintDrive."""
    result = simulate("SOFTLIMITMODE.0 = 4\n", controller="mintdrive")
    assert result.stop.reason is StopReason.ERROR
    assert "SOFTLIMITMODE" in result.stop.message
    assert "not simulated" in result.stop.message.lower()


def test_a_move_cancelled_on_its_limit_is_gone_for_good() -> None:
    """CANCEL ends the held move (000:16066-16067) and clears AXISERROR: leaving mode 4 afterwards starts
    nothing, and a later error in mode 2 calls #ONERROR again while it stays latched (AX-7), so the run
    stops after 100 re-entries. The axis rests on 100 from the smart stop to the end."""
    source = (
        "DIM n\nSOFTLIMITFORWARD.0 = 100 : SOFTLIMITMODE.0 = 4\nMOVEA.0 = 200 : GO.0\nPAUSE n = 1\n"
        'CANCEL.0\nSOFTLIMITMODE.0 = 2\nWAIT = 100\nPRINT POS.0, " ", IDLE.0\nSOFTLIMITFORWARD.0 = 50\n'
        "MOVEA.0 = 300 : GO.0\nPAUSE n > 1\nWAIT = 50\nEND\n#ONERROR\nn = n + 1\nRETURN\n"
    )
    result = simulate(source)
    assert result.terminal.startswith("100 1\n")
    assert result.stop.reason is StopReason.ERROR
    assert "#ONERROR returned 100 times" in result.stop.message
