"""Positional moves, vectors and jogs follow the manual's profile, buffer and GO rules (spec §3)."""

from __future__ import annotations

import itertools
import math

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import run_source
from mintlang.runtime.simulation import Limits
from tests.runtime.running import simulate


def trapezoid_ms(distance: float, speed: float, accel: float, decel: float) -> float:
    """The closed form of MP-8, in milliseconds."""
    ramps = speed * speed / (2 * accel) + speed * speed / (2 * decel)
    if distance >= ramps:
        return 1000 * (speed / accel + speed / decel + (distance - ramps) / speed)
    peak = math.sqrt(2 * distance * accel * decel / (accel + decel))
    return 1000 * (peak / accel + peak / decel)


def test_a_move_starts_on_the_next_profiler_tick_and_ends_on_the_first_one_after_its_duration() -> None:
    # RTM: GO at t=0 starts at 2 ms; the move is over at the first profiler tick with tau >= T
    result = simulate('MOVER.0 = 4000 : GO.0\nPAUSE IDLE.0\nPRINT TIME, " ", POS.0\n')
    duration = trapezoid_ms(4000, 20000, 300000, 300000)
    end = 2 + 2 * math.ceil(duration / 2)
    assert result.terminal == f"{end} 4000\n"


def test_separate_accel_and_decel_shape_a_triangle_when_the_move_is_short() -> None:
    # AXISMODE is 0 from the move's end (IDLE also waits for VEL to read 0 over its 2 ms sample)
    source = "ACCEL.0 = 100000 : DECEL.0 = 400000\nMOVER.0 = 500 : GO.0\nPAUSE AXISMODE.0 = 0\nPRINT TIME\n"
    end = 2 + 2 * math.ceil(trapezoid_ms(500, 20000, 100000, 400000) / 2)
    assert simulate(source).terminal == f"{end}\n"


def test_relative_moves_are_relative_to_the_last_target() -> None:
    # [000:15247-15255] and [000:3112-3117]
    source = "MOVEA.0 = 100 : GO.0\nPRINT POSTARGET.0\nMOVER.0 = 50 : GO.0\nPRINT POSTARGET.0\n"
    source += "PAUSE IDLE.0\nPRINT POS.0\n"
    assert simulate(source).terminal == "100\n150\n150\n"


def test_one_move_in_a_buffer_of_two_leaves_one_free() -> None:
    # [000:2978-2984]
    assert simulate("MOVER.0 = 100\nPRINT MOVEBUFFERFREE.0\n").terminal == "1\n"


def test_a_vector_ends_every_axis_on_its_target_together() -> None:
    source = 'VECTORA[0,1] = 300, 400 : GO[0,1]\nPAUSE IDLE[0,1]\nPRINT POS.0, " ", POS.1, " ", TIME\n'
    end = 2 + 2 * math.ceil(trapezoid_ms(500, 20000, 300000, 300000) / 2)
    assert simulate(source).terminal == f"300 400 {end}\n"


def test_vector_targets_follow_the_manuals_example() -> None:
    # [000:17055-17060]
    source = "VECTORA[1,2] = 100, 100 : GO[1,2]\nVECTORR[1,2] = 100, 200 : GO[1,2]\n"
    source += 'PAUSE IDLE[1,2]\nPRINT POS.1, " ", POS.2\n'
    assert simulate(source).terminal == "200 300\n"


def test_scale_converts_user_units_to_counts() -> None:
    # [000:2801-2806]: SCALE = 100 : SPEED = 10 is 1000 counts/s
    source = "SCALE.0 = 100 : SPEED.0 = 10\nMOVER.0 = 2 : GO.0\n"
    source += 'PAUSE IDLE.0\nPRINT POS.0, " ", ENCODER.0, " ", SPEED.0\n'
    assert simulate(source).terminal == "2 200 10\n"


def test_jog_runs_until_stopped_and_stop_decelerates_at_decel() -> None:
    source = """JOG.0 = 1000
WAIT = 500
PRINT AXISMODE.0, " ", VEL.0
STOP.0
PAUSE IDLE.0
PRINT AXISMODE.0
"""
    result = simulate(source)
    assert result.terminal == "4 1000\n0\n"
    assert 480 <= result.axes[0].pos <= 500


def test_a_move_on_a_disabled_drive_is_error_40() -> None:
    result = simulate("MOVER.0 = 10\n", enable=False)
    assert (result.stop.reason, result.err) == (StopReason.ERROR, 40)


def test_go_on_a_jogging_axis_is_motion_in_progress() -> None:
    # [000:11119-11128], kept in the corpus as a run-time-only error
    source = "AXES[0,1]\nJOG[1] = 100\nMA = 10 : GO\n"
    result = simulate(source)
    assert (result.err, result.erl) == (10, 3)


def test_speed_written_during_a_move_changes_the_move_in_progress() -> None:
    slow = simulate("MOVER.0 = 4000 : GO.0\nPAUSE IDLE.0\nPRINT TIME\n").terminal
    fast = simulate('MOVER.0 = 4000 : GO.0\nWAIT = 50\nSPEED.0 = 40000\nPAUSE IDLE.0\nPRINT TIME, " ", POS.0\n')
    finished, position = fast.terminal.split()
    assert int(finished) < int(slow)
    assert position == "4000"


def test_cancel_stops_at_once_and_reset_zeroes_the_position() -> None:
    source = 'JOG.0 = 2000\nWAIT = 100\nCANCEL.0\nWAIT = 10\nPRINT VEL.0, " ", FOLERROR.0\nRESET.0\nPRINT POS.0\n'
    assert simulate(source).terminal == "0 0\n0\n"


def test_a_vector_with_fewer_values_than_default_axes_interpolates_the_first_ones() -> None:
    # [000:3208]: VECTORA = 30,40 with the default AXES moves axes 0 and 1 along one line
    source = 'VECTORA = 30, 40 : GO\nPAUSE IDLE[0,1]\nPRINT POS.0, " ", POS.1, " ", POS.2\n'
    assert simulate(source).terminal == "30 40 0\n"


def test_a_rate_change_during_a_vector_keeps_its_axes_on_one_line() -> None:
    source = """VECTORA[0,1] = 3000, 4000 : GO[0,1]
WAIT = 50
SPEED.0 = 40000
WAIT = 20
PRINT POS.0 * 4 - POS.1 * 3
PAUSE IDLE[0,1]
PRINT POS.0, " ", POS.1
"""
    first, last = simulate(source).terminal.splitlines()
    assert abs(float(first)) <= 4  # both axes re-planned together: still on the line 4x = 3y
    assert last == "3000 4000"


def test_dac_is_written_directly_only_on_an_axis_configured_off() -> None:
    assert simulate("DRIVEENABLE.2 = 0 : CONFIG.2 = _cfOFF\nDAC.2 = 25\nWAIT = 5\nPRINT DAC.2\n").terminal == "25\n"
    assert simulate("DAC.2 = 25\n").err == 11


def test_acceltime_sets_the_rate_that_reaches_speed_in_that_time() -> None:
    # MP-4: SPEED = 5 : DECELTIME = 5000 gives DECEL = 1 [000:8965-8969]
    source = 'SPEED.0 = 5 : DECELTIME.0 = 5000 : ACCELTIME.0 = 2500\nPRINT DECEL.0, " ", ACCEL.0\n'
    assert simulate(source).terminal == "1 2\n"


def test_the_times_set_rates_beyond_the_range_accel_and_decel_take() -> None:
    # 000:6258-6261, 8971-8974: 20000 counts/s reached in 1 ms is 20,000,000 counts/s², above ACCEL's 8388607
    source = 'SPEED.0 = 20000 : ACCELTIME.0 = 1 : DECELTIME.0 = 2\nPRINT ACCEL.0, " ", DECEL.0\n'
    assert simulate(source).terminal == "20000000 10000000\n"


@pytest.mark.parametrize(("keyword", "accepted"), [("ACCELTIME", "1 to 8388607"), ("DECELTIME", "0 to 8388607")])
def test_a_time_outside_its_table_is_error_3(keyword: str, accepted: str) -> None:
    # 000:6232-6234, 8953-8955: ACCELTIME takes 1 ms and more, DECELTIME 0 and more
    below = 0 if keyword == "ACCELTIME" else -1
    result = simulate(f"{keyword}.0 = {below}\n")
    assert result.err == 3 and f"it takes {accepted}" in result.stop.message


def test_deceltime_zero_stops_a_jog_at_once() -> None:
    # 000:8957-8959: DECELTIME is the time from SPEED to rest, so 0 brings STOP to rest without a ramp: the demand
    # stops on the profiler tick after STOP (T-6), and two ticks later the axis has not moved
    source = "DIM a\nDECELTIME.0 = 0\nJOG.0 = 1000\nWAIT = 100\nSTOP.0\nWAIT = 2\na = POS.0\nWAIT = 2\n"
    assert simulate(source + 'PRINT POS.0 - a, " ", IDLE.0\n').terminal == "0 1\n"


def test_switch_keywords_read_the_inputs_assigned_to_the_axis() -> None:
    source = """REM @sim input 4 1 at 10
LIMITFORWARDINPUT.0 = 4 : LIMITMODE.0 = 0 : STOPINPUT.1 = 4 : STOPINPUTMODE.1 = 0
PRINT LIMIT.0, STOPSWITCH.1, LIMITREVERSE.0
WAIT = 20
PRINT LIMIT.0, LIMITFORWARD.0, STOPSWITCH.1, LIMITREVERSE.0, ERRORSWITCH.0
"""
    assert simulate(source).terminal == "000\n11100\n"


def test_loading_into_a_full_buffer_waits_until_a_move_finishes() -> None:
    # MP-25: the third move of a two-move buffer suspends the program until the first one is done
    source = """MOVER.0 = 1000 : GO.0
MOVER.0 = 1000 : GO.0
MOVER.0 = 1000 : GO.0
PRINT "third loaded at ", TIME, " free ", MOVEBUFFERFREE.0
PAUSE IDLE.0
PRINT POS.0
"""
    first_move_ends = 2 + 2 * math.ceil(trapezoid_ms(1000, 20000, 300000, 300000) / 2)
    assert simulate(source).terminal == f"third loaded at {first_move_ends} free 0\n3000\n"


@pytest.mark.parametrize("command", ["CANCEL.0", "CANCEL.1", "RESET.0", "DRIVEENABLE.0 = 0"])
def test_cancelling_or_disabling_one_axis_of_a_vector_stops_its_partner_too(command: str) -> None:
    # MP-14: the axes of a vector share one path; BEHAVIOUR "Interpolated moves and stops"
    source = f"""SPEED.0 = 1000 : ACCEL.0 = 10000 : DECEL.0 = 10000
VECTORR[0,1] = 3000, 4000 : GO.1
WAIT = 500
{command}
PRINT AXISMODE.0, " ", AXISMODE.1
WAIT = 100
PRINT VEL.0, " ", VEL.1
"""
    assert simulate(source).terminal == "0 0\n0 0\n"


def demands(source: str) -> list[float]:
    """The servo demand of axis 0 at every tick."""
    points: list[float] = []
    run_source(
        source,
        config="RESETALL\n",
        controller="nextmove-bx",
        limits=Limits(until_ms=60_000, every_tick=True),
        on_tick=lambda c, tick: points.append(c.axes[0].demand),
    )
    return points


@pytest.mark.parametrize("command", ["SPEED.0 = 10001", "DECEL.0 = 200000", "STOP.0"])
def test_a_command_issued_on_an_even_tick_leaves_no_step_in_the_demand(command: str) -> None:
    # T-6: the command acts at the next profiler tick; the tick between is the mean of the set-points
    # either side, the one already output and the first of the new plan (the WAIT ends on tick 500)
    source = f"SPEED.0 = 10000 : ACCEL.0 = 100000 : DECEL.0 = 100000\nJOG.0 = 10000\nWAIT = 500\n{command}\nWAIT = 50\n"
    steps = [after - before for before, after in itertools.pairwise(demands(source)[495:510])]
    assert steps[:6] == [10.0] * 6
    assert max(steps) <= 10.0 + 1e-9 and min(steps) >= 0.0
    simulate(source)


def test_torque_cannot_blend_from_a_vector_a_circle_or_a_homing_cycle() -> None:
    # [000:16865-16871]: error 10, and the move goes on
    source = """VECTORR[0,1] = 10000, 10000 : GO.0
WAIT = 10
TORQUE.0 = 5
PRINT AXISMODE.0, " ", AXISMODE.1
CIRCLER[0,1] = 10, 0, 90 : GO.0
TORQUE.1 = 5
HOMEINPUT.2 = 5 : HOME.2 = 0
TORQUE.2 = 5
PRINT AXISMODE.2
END
#ONERROR
PRINT "error ", ERR, " axis ", ERRAXIS
RETURN
"""
    assert simulate(source).terminal == "error 10 axis 0\n2 2\nerror 10 axis 1\nerror 10 axis 2\n32\n"


def test_torque_writes_the_dac_at_once() -> None:
    # [000:16865-16867]: the DAC output changes as TORQUE is written
    assert simulate('TORQUE.0 = 50 : PRINT DAC.0, " ", AXISMODE.0\n').terminal == "50 16\n"


def test_demand_is_mint_v3s_name_for_the_dac_and_no_v4_keyword() -> None:
    result = simulate("TORQUE.0 = 25\nPRINT DEMAND.0\n")
    assert result.stop.reason is StopReason.ERROR and result.terminal == "C3007: PROGRAM Keyword not defined [line 2]\n"
    assert "C3007" in result.stop.message and "replaced by DAC" in result.stop.message


def test_the_position_counter_wraps_past_8388607_and_absolute_moves_go_from_where_it_reads() -> None:
    # [000:14617-14618], MP-5 RC: the counter wraps modulo 2^24 counts into [-8388608, 8388607]
    source = """POS.0 = 8388000
MOVER.0 = 1000 : GO.0
PRINT POSTARGET.0
PAUSE IDLE.0
PRINT POS.0, " ", ENCODER.0
MOVEA.0 = -8388000 : GO.0
PAUSE IDLE.0
PRINT POS.0, " ", ENCODER.0
"""
    assert simulate(source).terminal == "-8388216\n-8388216 1000\n-8388000 1216\n"


def test_posremaining_right_after_go_is_the_whole_move() -> None:
    # v4 guide 3129-3134: MR = 200 : GO.0 then ? POSREMAINING "will return 200"
    assert simulate("RESET.0\nMR = 200 : GO.0\n? POSREMAINING\n").terminal == "200\n"


def test_pause_posremaining_waits_for_the_end_of_the_move() -> None:
    # v4 guide 15195-15205. Defaults SPEED 20000, ACCEL = DECEL 300000: under 100 counts are left once the
    # speed falls below sqrt(2 * 300000 * 100) = 7746 counts/s, 25.8 ms before the end at 2 + 566.7 ms.
    source = "RESET.0\nMOVER = 10000 : GO\nPAUSE POSREMAINING < 100\nOUT.2 = 1\nPRINT TIME\n"
    result = simulate(source)
    assert result.terminal == "543\n"


def test_posremaining_counts_the_move_in_progress_not_those_queued_behind_it() -> None:
    # v4 guide 15198 "the remaining distance to go for the current move" (MP-11); POSTARGET is the last one loaded
    source = "RESET.0\nSPEED.0 = 1000 : ACCEL.0 = 10000 : DECEL.0 = 10000\nMOVER.0 = 1000\nMOVER.0 = 1000\nGO.0\n"
    source += 'WAIT = 500\nPRINT POS.0, " ", POSREMAINING.0, " ", POSTARGET.0\n'
    assert simulate(source).terminal == "448 552 2000\n"


def test_the_same_vector_queued_twice_is_two_moves_and_go_on_one_axis_starts_each() -> None:
    # MP-28: GO on one axis of a vector starts it on all; equal loads are still separate moves
    source = (
        "MOVEBUFFERSIZE[0,1] = 4;\nVECTORA[0,1] = 100, 100\nVECTORA[0,1] = 0, 0\nVECTORA[0,1] = 100, 100\n"
        'GO.0\nPAUSE IDLE.0 AND IDLE.1\nPRINT POS.0, " ", POS.1\n'
    )
    result = simulate(source, until_ms=20_000)
    assert (result.stop.reason, result.terminal) == (StopReason.END, "100 100\n")


def test_a_deadlock_on_a_full_move_buffer_says_which_axis_is_full() -> None:
    # 000:572-580: one value for two axes sets only the first, so axis 1 keeps its buffer of 2 (MP-25)
    source = "MOVEBUFFERSIZE[0,1] = 5\nVECTORR[0,1] = 100,100\nCIRCLER[0,1] = 100,100,90\n"
    source += "VECTORR[0,1] = 100,0\nGO[0,1]\n"
    result = simulate(source)
    assert result.stop.reason is StopReason.DEADLOCK and result.stop.line == 4
    assert "move buffer of axis 1 is full (2 moves)" in result.stop.message


def test_posremaining_of_a_vector_is_the_remaining_vector_length() -> None:
    # 000:16978-16979: "The remaining vector length can be read using POSREMAINING": 300,400 is 500 long
    source = "VECTORR[0,1] = 300,400 : GO[0,1]\nPRINT POSREMAINING.0; POSREMAINING.1\n"
    source += "PAUSE IDLE[0,1]\nPRINT POSREMAINING.1\n"
    assert simulate(source).terminal == "500     500\n0\n"
