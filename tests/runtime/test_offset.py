"""OFFSET on NextMove: a relative move at SPEED that needs GO and shows _mdOFFSET, on an idle axis or on top of a
FOLLOW move (spec MP-18, 000:14774-14812)."""

from __future__ import annotations

import math

from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate


def trapezoid_ms(distance: float, speed: float, accel: float, decel: float) -> float:
    ramps = speed * speed / (2 * accel) + speed * speed / (2 * decel)
    if distance >= ramps:
        return 1000 * (speed / accel + speed / decel + (distance - ramps) / speed)
    peak = math.sqrt(2 * distance * accel * decel / (accel + decel))
    return 1000 * (peak / accel + peak / decel)


def test_an_offset_moves_the_idle_axis_by_its_distance_at_speed() -> None:
    source = (
        "OFFSET.0 = 5000 : GO.0\n"
        'WAIT = 10\nPRINT AXISMODE.0, " ", POSTARGET.0\n'
        'PAUSE IDLE.0\nPRINT POS.0, " ", TIME, " ", AXISMODE.0\n'
    )
    end = 2 + 2 * math.ceil(trapezoid_ms(5000, 20000, 300000, 300000) / 2)
    assert simulate(source).terminal == f"64 5000\n5000 {end} 0\n"


def test_an_offset_is_relative_and_may_be_negative() -> None:
    source = "MOVEA.0 = 1000 : GO.0\nPAUSE IDLE.0\nOFFSET.0 = -300 : GO.0\nPAUSE IDLE.0\nPRINT POS.0\n"
    assert simulate(source).terminal == "700\n"


def test_an_offset_waits_for_go() -> None:
    assert simulate('OFFSET.0 = 5000\nWAIT = 50\nPRINT AXISMODE.0, " ", POS.0\n').terminal == "0 0\n"


def test_only_one_offset_at_a_time() -> None:
    # [000:14786-14789]: a second OFFSET while the first runs is refused on NextMove
    result = simulate("OFFSET.0 = 5000 : GO.0\nWAIT = 10\nOFFSET.0 = 100\n")
    assert (result.stop.reason, result.err) == (StopReason.ERROR, 10)


def test_an_offset_needs_an_idle_axis_when_not_following() -> None:
    result = simulate("MOVER.0 = 5000 : GO.0\nOFFSET.0 = 100\n")
    assert (result.stop.reason, result.err) == (StopReason.ERROR, 10)


def test_stop_ends_an_offset_with_a_ramp() -> None:
    result = simulate("SPEED.0 = 1000 : DECEL.0 = 2000\nOFFSET.0 = 50000 : GO.0\nWAIT = 1000\nSTOP.0\nPAUSE IDLE.0\n")
    # cruising at 1000 counts/s, the DECEL ramp adds 1000²/(2·2000) = 250 counts
    assert 1000 + 250 - 10 < result.axes[0].pos < 1000 + 250 + 10
    assert result.axes[0].axismode == 0


FOLLOWING = (
    "MASTERCHANNEL.0 = 1\nFOLLOWMODE.0 = 0\nSPEED.0 = 5000 : ACCEL.0 = 50000 : DECEL.0 = 50000\n"
    "JOG.1 = 1000\nFOLLOW.0 = 1\n"
)


def test_an_offset_on_a_follow_move_runs_on_top_of_the_masters_speed() -> None:
    # 5000 counts at 5000 counts/s, ramps of 50000 counts/s2: 1.1 s on top of the 1:1 follow
    # (the slave follows the master's sample of the last profiler tick: read both once the master is at rest)
    source = FOLLOWING + "OFFSET.0 = 5000 : GO.0\nPRINT AXISMODE.0\nPAUSE !(AXISMODE.0 & _mdOFFSET)\nPRINT TIME\n"
    source += 'STOP.1\nPAUSE IDLE.1\nWAIT = 10\nPRINT POS.0 - POS.1, " ", AXISMODE.0\n'
    end = 2 + 2 * math.ceil(trapezoid_ms(5000, 5000, 50000, 50000) / 2)
    assert simulate(source, until_ms=5000).terminal == f"192\n{end}\n5000 128\n"


def test_a_second_offset_on_a_follow_move_waits_for_the_first() -> None:
    result = simulate(FOLLOWING + "OFFSET.0 = 5000 : GO.0\nWAIT = 10\nOFFSET.0 = 100\n", until_ms=2000)
    assert (result.stop.reason, result.err) == (StopReason.ERROR, 10)


def test_stop_cancels_an_offset_on_a_follow_move_where_it_is() -> None:
    # 000:14806-14808: the OFFSET is cancelled at once; FOLLOWMODE 0 stops the slave at once too
    source = FOLLOWING + "OFFSET.0 = 5000 : GO.0\nWAIT = 100\nSTOP.0\nPRINT AXISMODE.0\n"
    result = simulate(source, until_ms=2000)
    assert result.terminal == "0\n"
    assert 0 < result.axes[0].pos - 1000 * 0.1 < 5000
