"""CIRCLEA / CIRCLER trace an exact arc at the master's path speed and need GO (spec MP-15)."""

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


def end_tick(start: int, duration_ms: float) -> int:
    return start + 2 * math.ceil(duration_ms / 2 - 1e-9)


def trace(source: str, axes: tuple[int, int] = (0, 1)) -> list[tuple[int, float, float]]:
    """(tick, demand of the two axes) at every tick, with the axes enabled first."""
    points: list[tuple[int, float, float]] = []
    run_source(
        source,
        config="RESETALL\n",
        controller="nextmove-bx",
        limits=Limits(until_ms=60_000, every_tick=True),
        on_tick=lambda c, tick: points.append((tick, c.axes[axes[0]].demand, c.axes[axes[1]].demand)),
    )
    return points


FROM_30_30 = "MOVEA[0,1] = 30, 30 : GO[0,1]\nPAUSE IDLE[0,1]\n"


def test_the_manuals_half_circle_from_30_30_about_20_20_ends_at_10_10() -> None:
    # [000:3257-3263]
    source = FROM_30_30 + (
        "CIRCLEA[0,1] = 20, 20, 180 : GO[0,1]\n"
        'PRINT POSTARGET.0, " ", POSTARGET.1\n'
        "PAUSE IDLE[0,1]\n"
        'PRINT POS.0, " ", POS.1\n'
    )
    assert simulate(source).terminal == "10 10\n10 10\n"


def test_the_same_half_circle_with_a_relative_centre() -> None:
    source = FROM_30_30 + 'CIRCLER[0,1] = -10, -10, 180 : GO[0,1]\nPAUSE IDLE[0,1]\nPRINT POS.0, " ", POS.1\n'
    assert simulate(source).terminal == "10 10\n"


def test_a_negative_angle_turns_clockwise() -> None:
    # from (10000, 0) a quarter turn clockwise about the origin ends at (0, -10000)
    source = (
        "MOVEA[0,1] = 10000, 0 : GO[0,1]\nPAUSE IDLE[0,1]\n"
        'CIRCLER[0,1] = -10000, 0, -90 : GO[0,1]\nPAUSE IDLE[0,1]\nPRINT POS.0, " ", POS.1\n'
    )
    assert simulate(source).terminal == "0 -10000\n"


def test_every_point_of_a_full_circle_lies_on_it_and_the_path_speed_never_exceeds_speed() -> None:
    points = trace(
        "MOVEA[0,1] = 10000, 0 : GO[0,1]\nPAUSE IDLE[0,1]\nCIRCLEA[0,1] = 0, 0, 360 : GO[0,1]\nPAUSE IDLE[0,1]\n"
    )
    start = next(i for i, (_, x, y) in enumerate(points) if abs(y) > 0.0)
    arc = points[start - 1 :]
    assert all(abs(math.hypot(x, y) - 10000.0) <= 0.5 for _, x, y in arc)
    speeds = [math.hypot(x1 - x0, y1 - y0) * 1000.0 for (_, x0, y0), (_, x1, y1) in itertools.pairwise(arc)]
    assert max(speeds) <= 20000.0 + 1e-6
    assert arc[-1][1:] == (10000.0, 0.0)


def test_a_full_circle_takes_the_closed_form_time_of_its_arc_length() -> None:
    # path length 2·π·10000 at SPEED 20000, ACCEL = DECEL = 300000 (the defaults) along the path; GO at 0 starts at 2
    source = 'CIRCLER[0,1] = -10000, 0, 360 : GO[0,1]\nPAUSE IDLE[0,1]\nPRINT TIME, " ", POS.0, " ", POS.1\n'
    arc_ms = trapezoid_ms(2 * math.pi * 10000, 20000, 300000, 300000)
    assert simulate(source).terminal == f"{end_tick(2, arc_ms)} 0 0\n"


def test_more_than_one_turn_is_allowed_and_ends_where_it_started() -> None:
    # MP-15 RC: |angle| > 360 means several turns
    source = (
        "MOVEA[0,1] = 1000, 0 : GO[0,1]\nPAUSE IDLE[0,1]\n"
        'CIRCLEA[0,1] = 0, 0, 720 : GO[0,1]\nPAUSE IDLE[0,1]\nPRINT POS.0, " ", POS.1\n'
    )
    assert simulate(source).terminal == "1000 0\n"


def test_the_master_axis_sets_the_path_speed() -> None:
    # SPEED of axis 1 does not matter; axis 0 (first named) is the master [000:8174-8176]
    slow = "SPEED.0 = 5000 : SPEED.1 = 100\n"
    source = slow + "CIRCLER[0,1] = 0, 1000, 180 : GO[0,1]\nPAUSE IDLE[0,1]\nPRINT TIME\n"
    arc_ms = trapezoid_ms(math.pi * 1000, 5000, 300000, 300000)
    assert simulate(source).terminal == f"{end_tick(2, arc_ms)}\n"


def test_a_circle_shows_mode_8_and_waits_for_go() -> None:
    source = (
        "CIRCLER[0,1] = 0, 1000, 90\nWAIT = 10\n"
        'PRINT AXISMODE.0, " ", MOVEBUFFERFREE.0\n'
        "GO[0,1]\nWAIT = 10\n"
        'PRINT AXISMODE.0, " ", AXISMODE.1\n'
    )
    assert simulate(source).terminal == "0 1\n8 8\n"


def test_go_on_either_axis_starts_the_circle() -> None:
    # [000:11096-11100]; from (0,0) a quarter turn anticlockwise about (0,1000) ends at (1000,1000)
    source = 'CIRCLER[0,1] = 0, 1000, 90 : GO.1\nPAUSE IDLE[0,1]\nPRINT POS.0, " ", POS.1\n'
    assert simulate(source).terminal == "1000 1000\n"


def test_postarget_reads_each_axis_end_point_and_relative_moves_continue_from_it() -> None:
    source = (
        "CIRCLER[0,1] = 0, 1000, 90 : GO[0,1]\n"
        'PRINT POSTARGET.0, " ", POSTARGET.1\n'
        "VECTORR[0,1] = 500, 0 : GO[0,1]\n"
        'PRINT POSTARGET.0, " ", POSTARGET.1\n'
        "PAUSE IDLE[0,1]\n"
        'PRINT POS.0, " ", POS.1\n'
    )
    assert simulate(source).terminal == "1000 1000\n1500 1000\n1500 1000\n"


def test_a_circle_takes_a_centre_and_an_angle() -> None:
    assert simulate("CIRCLER[0,1] = 0, 1000\n").err == 2001
    assert simulate("CIRCLER[0,1] = 0, 1000, 90, 5\n").err == 2017


def test_a_circle_cannot_start_on_a_jogging_axis() -> None:
    result = simulate("JOG.1 = 100\nCIRCLER[0,1] = 0, 1000, 90\n")
    assert (result.stop.reason, result.err) == (StopReason.ERROR, 10)


@pytest.mark.parametrize(
    "values",
    [
        pytest.param("8388608, 0, 90", id="centre above the range"),
        pytest.param("0, -8388609, 90", id="second coordinate below it"),
        pytest.param("100, 0, 8388608", id="angle above it"),
    ],
)
@pytest.mark.parametrize("keyword", ["CIRCLEA", "CIRCLER"])
def test_each_value_is_in_the_tables_range(keyword: str, values: str) -> None:
    # 000:8163-8165, 8220-8222: every value -8388608 to 8388607
    result = simulate(f"{keyword}[0,1] = {values}\n")
    assert (result.err, result.erl) == (3, 1)
    assert "it takes -8388608 to 8388607" in result.stop.message


def test_the_centre_is_in_range_after_scale_and_the_angle_as_written() -> None:
    # 000:5648-5649: a scaled value's range is for the value times SCALE; the angle is in degrees, not scaled
    result = simulate("SCALE[0,1] = 1000, 1000\nCIRCLER[0,1] = 9000, 0, 90\n")
    assert (result.err, result.erl) == (3, 2) and "9000000 at SCALE 1000" in result.stop.message
    accepted = simulate('SCALE[0,1] = 1000, 1000\nCIRCLER[0,1] = 1, 0, 9000\nPRINT POSTARGET.0, " ", POSTARGET.1\n')
    assert accepted.terminal == "0 0\n"  # 25 whole turns end where they began
