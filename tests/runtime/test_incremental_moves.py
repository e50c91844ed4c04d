"""INCA / INCR: a positional move whose end point can change while it runs (spec MP-17)."""

from __future__ import annotations

from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import run_source
from mintlang.runtime.simulation import Limits
from tests.runtime.running import simulate


def test_the_manuals_example_turns_round_and_ends_at_55() -> None:
    # [000:3158-3166]: INCR adjusts the end point (100 - 45), not the current position
    source = (
        "SPEED.2 = 100 : ACCEL.2 = 1000 : DECEL.2 = 1000\n"
        "INCA.2 = 100 : GO.2\n"
        "PAUSE POS.2 > 75\n"
        "INCR.2 = -45\n"
        "PRINT POSTARGET.2\n"
        "PAUSE IDLE.2\n"
        'PRINT POS.2, " ", AXISMODE.2\n'
    )
    assert simulate(source).terminal == "55\n55 0\n"


def test_the_axis_decelerates_and_reverses_toward_the_new_end_point() -> None:
    source = (
        "SPEED.2 = 100 : ACCEL.2 = 1000 : DECEL.2 = 1000\n"
        "INCA.2 = 100 : GO.2\nPAUSE POS.2 > 75\nINCR.2 = -45\nPAUSE IDLE.2\n"
    )
    trace: list[float] = []
    run_source(
        source,
        config="RESETALL\n",
        controller="nextmove-bx",
        limits=Limits(until_ms=10_000, every_tick=True),
        on_tick=lambda c, tick: trace.append(c.axes[2].demand),
    )
    peak = max(trace)
    assert 75 < peak < 100  # it never reached the old end point
    assert trace.index(peak) < len(trace) - 1 and trace[-1] == 55.0


def test_incr_before_the_first_move_finishes_moves_its_end_point() -> None:
    # [000:12118-12125]
    source = 'INCA.2 = -50 : GO.2\nINCR.2 = 10 : GO.2\nPAUSE IDLE.2\nPRINT POS.2, " ", POSTARGET.2\n'
    assert simulate(source).terminal == "-40 -40\n"


def test_a_target_changed_while_moving_takes_effect_at_once() -> None:
    source = (
        "DIM p\nINCA.0 = 100000 : GO.0\nWAIT = 500\nINCA.0 = 0\nWAIT = 4\np = POS.0\nWAIT = 150\n"
        'PRINT POS.0 < p, " ", AXISMODE.0\nPAUSE IDLE.0\nPRINT POS.0\n'
    )
    assert simulate(source).terminal == "1 16384\n0\n"


def test_an_incremental_move_needs_go_and_shows_bit_14() -> None:
    source = 'INCA.0 = 1000\nWAIT = 20\nPRINT AXISMODE.0, " ", POS.0\nGO.0\nWAIT = 20\nPRINT AXISMODE.0\n'
    assert simulate(source).terminal == "0 0\n16384\n"


def test_an_inca_to_the_current_position_generates_no_move() -> None:
    # [000:3172-3173]
    assert simulate('INCA.0 = 0 : GO.0\nWAIT = 10\nPRINT AXISMODE.0, " ", IDLE.0\n').terminal == "0 1\n"


def test_the_first_incremental_move_needs_an_idle_axis() -> None:
    result = simulate("MOVER.0 = 100000 : GO.0\nINCA.0 = 10\n")
    assert (result.stop.reason, result.err) == (StopReason.ERROR, 10)


def test_stop_decelerates_an_incremental_move() -> None:
    source = "INCA.0 = 100000 : GO.0\nWAIT = 1000\nSTOP.0\nPAUSE IDLE.0\nPRINT AXISMODE.0\n"
    result = simulate(source)
    assert result.terminal == "0\n"
    assert 19000 < result.axes[0].pos < 21000
