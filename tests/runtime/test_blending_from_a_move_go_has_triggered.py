"""JOG and TORQUE cannot blend from an interpolated move GO has triggered but not yet started.

A move GO triggers starts at the next profiler tick; until then AXISMODE already shows it
(000:3033-3035), so a JOG or TORQUE in the same slice meets the same rule as one a tick later:
neither blends from VECTORA/R or CIRCLEA/R (000:12680-12686, 3945-3948, 16865-16871), which is error 10
(000:18543), and the interpolated move goes on on all its axes.
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
