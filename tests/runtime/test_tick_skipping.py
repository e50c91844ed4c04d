"""Skipping ticks where nothing can change gives the results of stepping every tick.

Every scenario test already runs both ways (``tests/runtime/running.py``); these
are the cases a review found where skipping once went wrong.
"""

from __future__ import annotations

from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate


def test_a_stalled_axis_trips_its_following_error_on_the_tick_it_passes_the_limit() -> None:
    source = "REM @sim plant 0 stalled\nFOLERRORFATAL.0 = 100\nMOVER.0 = 2000 : GO.0\nPAUSE IDLE.0\n"
    result = simulate(source)
    assert result.stop.reason is StopReason.ERROR
    assert result.stop.time_ms < 200  # 100 counts of error, early in the ramp, not at the end of the move


def test_a_run_cut_off_mid_move_reports_the_axis_where_it_is() -> None:
    source = "SPEED.0 = 1000 : ACCEL.0 = 10000 : DECEL.0 = 10000\nMOVER.0 = 2000 : GO.0\nPAUSE IDLE.0\n"
    result = simulate(source, until_ms=1000)
    assert result.stop.reason is StopReason.UNTIL
    axis = result.axes[0]
    assert 900 < axis.pos < 1000 and axis.vel == 1000 and axis.axismode == 2


def test_a_full_buffer_after_an_earlier_wait_is_still_a_deadlock() -> None:
    result = simulate("WAIT = 5\nMOVEBUFFERSIZE.0 = 2\nMOVER.0 = 10\nMOVER.0 = 10\nMOVER.0 = 10\n")
    assert (result.stop.reason, result.stop.line) == (StopReason.DEADLOCK, 5)


def test_a_stalled_axis_reads_no_velocity_after_skipped_ticks() -> None:
    source = 'REM @sim plant 0 stalled\nMOVER.0 = 500 : GO.0\nWAIT = 800\nPRINT VEL.0, " ", IDLE.0\n'
    assert simulate(source).terminal == "0 1\n"


def test_an_unhandled_motion_error_names_the_file_and_the_line() -> None:
    source = "REM @sim plant 0 stalled\nFOLERRORFATAL.0 = 100\nMOVER.0 = 2000 : GO.0\nPAUSE IDLE.0\n"
    message = simulate(source).stop.message
    assert message.startswith("R0500: PROGRAM Axis error present [axis/channel 0]") and message.endswith("[line 4]")


def test_a_program_blocked_for_good_deadlocks_once_its_moves_have_ended() -> None:
    # 1000 units/s reached in 0.1 s (50 units), left in 0.1 s (50 units), 1900 units at speed: 2.1 s.
    source = "SPEED.0 = 1000 : ACCEL.0 = 10000 : DECEL.0 = 10000\nMOVER.0 = 2000 : GO.0\nPAUSE IN1\n"
    result = simulate(source)
    assert (result.stop.reason, result.stop.line) == (StopReason.DEADLOCK, 3)
    assert 2100 <= result.stop.time_ms <= 2105  # GO starts the move on a profiler tick
    assert result.axes[0].pos == 2000 and result.axes[0].axismode == 0
