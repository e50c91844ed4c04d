"""Asynchronous motion errors: detection, default actions, #ONERROR and recovery (spec §4, EV-13..EV-19)."""

from __future__ import annotations

from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.scenario.stimulus import PlantChoice, Scenario
from tests.runtime.running import simulate

TUNED = "KPROP.0 = 0.5 : KDERIV.0 = 6 : KVELFF.0 = 0.2 : KACCEL.0 = 20\n"


def torque_plant() -> Scenario:
    return Scenario(plants=(PlantChoice(0, "torque"),))


def test_a_tuned_torque_plant_follows_a_move_to_its_target() -> None:
    result = simulate(TUNED + "MOVER.0 = 4000 : GO.0\nPAUSE IDLE.0\nWAIT = 200\n", scenario=torque_plant())
    assert result.stop.reason is StopReason.END
    assert abs(result.axes[0].pos - 4000) <= 2
    assert result.axes[0].axiserror == 0


def test_a_saturated_dac_trips_the_following_error_and_disables_the_drive() -> None:
    source = TUNED + "DACLIMITMAX.0 = 1\nMOVER.0 = 40000 : GO.0\nPAUSE IDLE.0\n"
    result = simulate(source, scenario=torque_plant())
    assert result.stop.reason is StopReason.ERROR
    assert result.stop.message.startswith("R0500")
    axis = result.axes[0]
    assert axis.axiserror & 32 and not axis.enabled


def test_onerror_reads_err_500_and_the_axis_and_cancel_clears_the_error() -> None:
    source = (
        TUNED
        + """DACLIMITMAX.0 = 1
MOVER.0 = 40000 : GO.0
PAUSE IDLE.0
PRINT "after ", AXISERROR.0, " ", DRIVEENABLE.0
END
#ONERROR
PRINT ERR, " axis ", ERRAXIS, " bits ", AXISERROR.0
CANCEL.0
RETURN
"""
    )
    result = simulate(source, scenario=torque_plant())
    assert result.terminal == "500 axis 0 bits 32\nafter 0 0\n"


def test_a_forward_limit_switch_crash_stops_and_disables_by_default() -> None:
    source = """REM @sim input 6 when enc 0 >= 1000
LIMITFORWARDINPUT.0 = 6
MOVER.0 = 5000 : GO.0
PAUSE IDLE.0
"""
    result = simulate(source)
    assert result.stop.reason is StopReason.ERROR
    axis = result.axes[0]
    assert axis.axiserror & 2 and not axis.enabled
    assert 1000 <= axis.pos < 1100
    assert result.stop.message.startswith("R0500")


def test_limitmode_ignore_only_shows_the_switch_in_axisstatus() -> None:
    source = """REM @sim input 6 when enc 0 >= 1000
LIMITFORWARDINPUT.0 = 6 : LIMITMODE.0 = 0
MOVER.0 = 2000 : GO.0
PAUSE IDLE.0
PRINT POS.0, " ", AXISERROR.0, " ", AXISSTATUS.0
"""
    assert simulate(source).terminal == "2000 0 2\n"


def test_a_reverse_limit_counts_only_when_stationary_or_moving_in_reverse() -> None:
    # AX-14 RC: crossing an active reverse limit while moving forward is fine; resting on it is not
    source = """REM @sim input 7 when enc 0 >= 100
LIMITREVERSEINPUT.0 = 7
MOVER.0 = 500 : GO.0
PAUSE POS.0 > 300
PRINT "moving ", AXISERROR.0
PAUSE IDLE.0
"""
    result = simulate(source)
    assert result.terminal == "moving 0\nR0500: PROGRAM Axis error present [axis/channel 0] [line 6]\n"
    assert result.axes[0].axiserror & 4 and result.axes[0].pos == 500


def test_a_software_limit_in_error_decel_mode_ramps_down_and_keeps_the_drive() -> None:
    source = """SOFTLIMITFORWARD.0 = 1000 : SOFTLIMITMODE.0 = 3 : ERRORDECEL.0 = 1000000
MOVER.0 = 5000 : GO.0
PAUSE IDLE.0
END
#ONERROR
PAUSE IDLE.0
PRINT AXISERROR.0, " ", DRIVEENABLE.0
RETURN
"""
    result = simulate(source)
    assert result.terminal.startswith("8 1\n")
    assert 1000 < result.axes[0].pos < 1300


def test_abort_latches_an_abort_error_on_every_axis() -> None:
    result = simulate("JOG[0,1] = 100, 200\nWAIT = 50\nABORT\n")
    assert result.stop.reason is StopReason.ERROR
    assert all(axis.axiserror & 1 and not axis.enabled for axis in result.axes)


def test_a_move_while_an_error_is_latched_is_error_12() -> None:
    source = "ABORT\nEND\n#ONERROR\nDIM tried = 0\nIF tried = 0 DO\n  tried = 1\n  MOVER.0 = 10\nENDIF\nRETURN\n"
    result = simulate(source)
    assert result.err == 12


def test_the_error_input_crash_stops_and_removes_the_drive_enable() -> None:
    # AX-16: ERRORINPUT raises _erERROR_INPUT (bit 7) with the default action of mode 1
    source = """REM @sim input 9 1 at 50
ERRORINPUT.0 = 9
JOG.0 = 1000
WAIT = 100
END
#ONERROR
PRINT "error ", ERR, " bits ", AXISERROR.0, " drive ", DRIVEENABLE.0, " switch ", ERRORSWITCH.0
RETURN
"""
    assert simulate(source).terminal.startswith("error 500 bits 128 drive 0 switch 1\n")


def test_a_velocity_amplifier_plant_moves_at_k_counts_per_second_per_percent() -> None:
    # W-1 velamp: with only proportional gain the axis follows its demand through the DAC
    source = "REM @sim plant 0 velamp 1000\nKPROP.0 = 1\nMOVER.0 = 2000 : GO.0\nPAUSE IDLE.0\nWAIT = 300\n"
    result = simulate(source)
    assert abs(result.axes[0].pos - 2000) <= 2


def test_error_decel_mode_calls_onerror_once_the_axis_is_at_rest() -> None:
    # [000:13505-13506] LIMITMODE 3: the handler runs once the demanded speed is zero (AX-13)
    source = """REM @sim input 1 1 at 300
REM @sim input 1 0 at 320
SPEED.0 = 1000 : ACCEL.0 = 10000 : DECEL.0 = 10000 : ERRORDECEL.0 = 2000
LIMITFORWARDINPUT.0 = 1 : LIMITMODE.0 = 3
MOVER.0 = 2000 : GO.0
PAUSE AXISERROR.0
PRINT "tripped ", TIME, " ", AXISMODE.0
PAUSE TIME > 2000
END
#ONERROR
PRINT "handler ", TIME, " ", AXISMODE.0, " ", VEL.0, " ", AXISERROR.0, " ", DRIVEENABLE.0
CANCEL.0
RETURN
"""
    # 1000 counts/s ramped down at 2000 counts/s² take 500 ms
    assert simulate(source).terminal == "tripped 300 2\nhandler 802 0 0 2 1\n"


def test_a_software_limit_trips_only_once_the_demand_is_past_it() -> None:
    # AX-15 RC: POS > SOFTLIMITFORWARD; the profile's rounding noise at exactly 500 does not count
    source = """SPEED.0 = 1000 : ACCEL.0 = 10000 : DECEL.0 = 10000
SOFTLIMITFORWARD.0 = 500 : SOFTLIMITMODE.0 = 1
MOVER.0 = 1000 : GO.0
PAUSE IDLE.0
END
#ONERROR
PRINT TIME, " ", POS.0, " ", AXISERROR.0
CANCEL.0
RETURN
"""
    assert simulate(source).terminal == "553 501 8\n"


def test_axisstatus_of_a_disabled_axis_shows_its_switches_as_they_are() -> None:
    # AX-6: AXISSTATUS is instantaneous; a disabled axis latches nothing (BEHAVIOUR, AX-5)
    source = """REM @sim plant 0 stalled
REM @sim input 1 1 at 1000
REM @sim input 1 0 at 1100
FOLERRORFATAL.0 = 100
MOVER.0 = 1000 : GO.0
PAUSE TIME = 500
LIMITFORWARDINPUT.0 = 1
PAUSE TIME = 1050
PRINT AXISSTATUS.0, " ", AXISERROR.0, " ", LIMITFORWARD.0
PAUSE TIME = 1150
PRINT AXISSTATUS.0, " ", AXISERROR.0
END
#ONERROR
CANCEL.0
PRINT "cancelled ", AXISSTATUS.0, " ", DRIVEENABLE.0
RETURN
"""
    assert simulate(source).terminal == "cancelled 0 0\n2 0 1\n0 0\n"


def test_errraxis_after_abort_names_the_first_axis() -> None:
    source = 'ABORT\nEND\n#ONERROR\nPRINT ERR, " ", ERRAXIS\nCANCELALL\nRETURN\n'
    assert simulate(source).terminal == "500 0\n"


def test_in_torque_mode_the_demand_follows_the_axis_and_stop_holds_where_it_is() -> None:
    # [000:2740-2767]: TORQUE turns the position loop off (no following error, so the default
    # FOLERRORFATAL does not trip); servoing restarts at the position the axis has reached
    source = (
        TUNED
        + """TORQUE.0 = 2
WAIT = 100
PRINT FOLERROR.0, " ", AXISERROR.0
DIM moved = POS.0
STOP.0
WAIT = 300
PRINT AXISMODE.0, " ", ABS(POS.0 - moved) < 20, " ", POS.0 > 200
"""
    )
    assert simulate(source, scenario=torque_plant()).terminal == "0 0\n0 1 1\n"
