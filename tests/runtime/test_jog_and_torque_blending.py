"""JOG and TORQUE blend from any move but a homing cycle, a vector or a circle (000:3945-3948).

Neither blends from VECTORA/R or CIRCLEA/R (000:12680-12686, 16865-16871): that is error 10 (000:18543)
and the interpolated move goes on on all its axes. A move GO has triggered starts at the next profiler
tick, but AXISMODE already shows it (000:3033-3035), so a JOG or TORQUE in the same slice meets the same
rule as one a tick later.
"""

from __future__ import annotations

import pytest

from tests.runtime.running import simulate

HANDLER = """END
#ONERROR
PRINT "error ", ERR, " axis ", ERRAXIS
RETURN
"""


@pytest.mark.parametrize(
    ("source", "terminal"),
    [
        pytest.param(
            # the vector (300, 400) is refused to JOG and still ends on its target on both axes
            'VECTORA[0,1] = 300, 400 : GO[0,1]\nJOG.0 = 10\nPAUSE IDLE[0,1]\nPRINT POS.0, " ", POS.1\n',
            "error 10 axis 0\n300 400\n",
            id="jog-after-a-vector-go",
        ),
        pytest.param(
            # JOG on the vector's second axis meets the same vector
            'VECTORA[0,1] = 300, 400 : GO[0,1]\nJOG.1 = 10\nPAUSE IDLE[0,1]\nPRINT POS.0, " ", POS.1\n',
            "error 10 axis 1\n300 400\n",
            id="jog-on-the-partner-axis",
        ),
        pytest.param(
            # CIRCLER from (0,0) about (100,0) through 180 degrees anticlockwise ends at (200,0) (000:3246-3253)
            'CIRCLER[0,1] = 100, 0, 180 : GO[0,1]\nTORQUE.1 = 5\nPAUSE IDLE[0,1]\nPRINT POS.0, " ", POS.1\n',
            "error 10 axis 1\n200 0\n",
            id="torque-after-a-circle-go",
        ),
        pytest.param(
            # a single-axis MOVE is not interpolated: JOG blends from it (000:12680-12686) and jogs (bit 4)
            "MOVER.0 = 1000 : GO.0\nJOG.0 = 10\nPRINT AXISMODE.0\n",
            "4\n",
            id="jog-after-a-move-go-blends",
        ),
    ],
)
def test_jog_and_torque_meet_a_triggered_move_as_a_running_one(source: str, terminal: str) -> None:
    assert simulate(source + HANDLER).terminal == terminal


RATES = "SPEED.0 = 1000 : ACCEL.0 = 2000 : DECEL.0 = 2000\n"


@pytest.mark.parametrize(
    ("source", "terminal"),
    [
        pytest.param(
            # JOG at tick 1000 acts at 1002, at 750 counts and 1000 counts/s; DECEL takes it to 500 counts/s in
            # 0.25 s over (1000^2 - 500^2)/(2*2000) = 187.5 counts, 937.5 at 1252; 0.748 s at 500 counts/s
            # more makes 1311.5 at 2000, which the encoder reads as 1312; VEL: 1 count in 2 ms is 500
            RATES + "INCA.0 = 10000 : GO.0\nWAIT = 1000\nJOG.0 = 500\nWAIT = 1000\n",
            "4 500 1312\n",
            id="from-an-incremental-move",
        ),
        pytest.param(
            # OFFSET on an idle axis is a relative move at SPEED (000:14774-14784): the same figures
            RATES + "OFFSET.0 = 10000 : GO.0\nWAIT = 1000\nJOG.0 = 500\nWAIT = 1000\n",
            "4 500 1312\n",
            id="from-an-offset",
        ),
        pytest.param(
            # a follower of an idle master jogs from rest at tick 12: ACCEL 1000 gives 500 counts/s at 512 after
            # 125 counts, and 498 ms at 500 counts/s more make 374 at tick 1010
            "ACCEL.0 = 1000\nMASTERSOURCE.0 = _msPOS : MASTERCHANNEL.0 = 1\nFOLLOW.0 = 1\nWAIT = 10\n"
            "JOG.0 = 500\nWAIT = 1000\n",
            "4 500 374\n",
            id="from-a-follow",
        ),
    ],
)
def test_jog_blends_from_any_move_but_a_homing_cycle_a_vector_or_a_circle(source: str, terminal: str) -> None:
    # 000:3945-3948: a JOG may blend from any other move type but those three
    assert simulate(source + 'PRINT AXISMODE.0, " ", VEL.0, " ", POS.0\n' + HANDLER).terminal == terminal
