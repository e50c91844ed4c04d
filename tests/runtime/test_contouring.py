"""CONTOURMODE blends consecutive path moves at constant path speed; CONTOURANGLE makes corners stop (MP-32..MP-34)."""

from __future__ import annotations

import itertools
import math

from mintlang.runtime.run import run_source
from mintlang.runtime.simulation import Limits
from tests.runtime.running import simulate


def trapezoid_ms(distance: float, speed: float = 20000, accel: float = 300000, decel: float = 300000) -> float:
    ramps = speed * speed / (2 * accel) + speed * speed / (2 * decel)
    if distance >= ramps:
        return 1000 * (speed / accel + speed / decel + (distance - ramps) / speed)
    peak = math.sqrt(2 * distance * accel * decel / (accel + decel))
    return 1000 * (peak / accel + peak / decel)


def end_tick(start: int, duration_ms: float) -> int:
    return start + 2 * math.ceil(duration_ms / 2 - 1e-9)


# [000:8203-8213] in counts (x1000): from (40,-20) a line to (80,20), then a quarter circle about (100,0) clockwise
MANUAL = (
    "POS[0,1] = 40000, -20000\n"
    "CONTOURMODE[0,1] = {mode}, {mode}\n"
    "VECTORA[0,1] = 80000, 20000 : GO[0,1]\n"
    "CIRCLEA[0,1] = 100000, 0, -90 : GO[0,1]\n"
    "PAUSE IDLE[0,1]\n"
    'PRINT TIME, " ", POS.0, " ", POS.1\n'
)
LINE = 40000 * math.sqrt(2)
ARC = math.hypot(20000, 20000) * math.pi / 2


def path_speeds(source: str) -> list[float]:
    """Path speed in counts/s of axes 0 and 1 at every tick (from the demand)."""
    points: list[tuple[float, float]] = []
    run_source(
        source,
        config="RESETALL\n",
        controller="nextmove-bx",
        limits=Limits(until_ms=60_000, every_tick=True),
        on_tick=lambda c, tick: points.append((c.axes[0].demand, c.axes[1].demand)),
    )
    return [math.hypot(x1 - x0, y1 - y0) * 1000.0 for (x0, y0), (x1, y1) in itertools.pairwise(points)]


def test_the_manuals_line_and_arc_run_as_one_profile_when_contoured() -> None:
    end = end_tick(2, trapezoid_ms(LINE + ARC))
    assert simulate(MANUAL.format(mode=1)).terminal == f"{end} 120000 20000\n"


def test_without_contouring_the_axes_stop_between_the_line_and_the_arc() -> None:
    line_end = end_tick(2, trapezoid_ms(LINE))
    end = end_tick(line_end, trapezoid_ms(ARC))
    assert simulate(MANUAL.format(mode=0)).terminal == f"{end} 120000 20000\n"


def test_the_path_speed_holds_at_speed_across_the_boundary_and_never_exceeds_it() -> None:
    speeds = path_speeds(MANUAL.format(mode=1))
    assert max(speeds) <= 20000.0 + 1e-6
    cruise = speeds[100 : len(speeds) - 100]  # past the 67 ms ramps at either end
    assert min(cruise) >= 20000.0 - 1.0


def test_the_mode_a_move_was_loaded_with_decides_whether_its_end_is_a_stop_point() -> None:
    # [000:8612-8630] (v4.2): only the end of the move loaded with contouring off stops
    source = (
        "MOVEBUFFERSIZE.0 = 10\nCONTOURMODE.0 = 1\nMOVER.0 = 10000\nMOVER.0 = 10000\n"
        "CONTOURMODE.0 = 0\nMOVER.0 = 10000\nCONTOURMODE.0 = 1\nMOVER.0 = 10000\nMOVER.0 = 10000\n"
        'GO.0\nPAUSE IDLE.0\nPRINT TIME, " ", POS.0\n'
    )
    end = end_tick(end_tick(2, trapezoid_ms(30000)), trapezoid_ms(20000))
    assert simulate(source).terminal == f"{end} 50000\n"


def test_with_angle_control_a_corner_at_or_above_contourangle_is_a_stop_point() -> None:
    # the keyword table's range (0 or 1) predates bit 1, so the checker refuses a literal 3: go through a variable
    corner = (
        "DIM m\nm = {mode}\nCONTOURMODE[0,1] = m, m\n"
        "VECTORR[0,1] = 10000, 0 : GO[0,1]\nVECTORR[0,1] = {x}, {y} : GO[0,1]\n"
    )
    tail = "PAUSE IDLE[0,1]\nPRINT TIME\n"
    square = end_tick(end_tick(2, trapezoid_ms(10000)), trapezoid_ms(10000))
    assert simulate(corner.format(mode=3, x=0, y=10000) + tail).terminal == f"{square}\n"
    # CONTOURANGLE 15 by default: a 5.7 degree bend blends
    shallow = end_tick(2, trapezoid_ms(10000 + math.hypot(10000, 1000)))
    assert simulate(corner.format(mode=3, x=10000, y=1000) + tail).terminal == f"{shallow}\n"
    # without angle control even a right angle blends (and jars the machine, [000:3272-3274])
    blended = end_tick(2, trapezoid_ms(20000))
    assert simulate(corner.format(mode=1, x=0, y=10000) + tail).terminal == f"{blended}\n"
    # a threshold of 90 degrees stops at exactly 90 (equals or exceeds, MP-33 RC)
    assert simulate("CONTOURANGLE.0 = 90\n" + corner.format(mode=3, x=0, y=10000) + tail).terminal == f"{square}\n"


def test_a_move_triggered_before_braking_begins_still_blends() -> None:
    source = "CONTOURMODE.0 = 1\nMOVER.0 = 20000 : GO.0\nWAIT = 500\nMOVER.0 = 20000 : GO.0\nPAUSE IDLE.0\nPRINT TIME\n"
    assert simulate(source).terminal == f"{end_tick(2, trapezoid_ms(40000))}\n"


def test_once_braking_has_begun_the_axis_stops_before_the_next_move() -> None:
    # [004:246]: braking for the first move starts at 1000 ms; the second arrives at 1020 ms
    source = (
        "CONTOURMODE.0 = 1\nMOVER.0 = 20000 : GO.0\nWAIT = 1020\nMOVER.0 = 20000 : GO.0\nPAUSE IDLE.0\nPRINT TIME\n"
    )
    first = end_tick(2, trapezoid_ms(20000))
    assert simulate(source).terminal == f"{end_tick(first, trapezoid_ms(20000))}\n"


def test_stop_during_a_contour_decelerates_along_the_path_and_clears_the_rest() -> None:
    source = MANUAL.format(mode=1).replace("PAUSE IDLE[0,1]\n", "WAIT = 1000\nSTOP.0\nPAUSE IDLE[0,1]\n")
    result = simulate(source)
    travelled = math.hypot(result.axes[0].pos - 40000, result.axes[1].pos + 20000)
    assert abs(travelled - (20000 * (1.002 - 1 / 30) + 20000**2 / 600000)) < 50
    assert (result.axes[0].axismode, result.axes[1].axismode) == (0, 0)


def test_contourmode_takes_0_1_or_3_and_contourangle_defaults_to_15() -> None:
    assert simulate('DIM m\nm = 3\nCONTOURMODE.0 = m\nPRINT CONTOURMODE.0, " ", CONTOURANGLE.0\n').terminal == "3 15\n"
    assert simulate("DIM m\nm = 2\nCONTOURMODE.0 = m\n").err == 3
