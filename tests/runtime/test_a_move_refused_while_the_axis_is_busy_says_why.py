"""A linear move refused because its axis is busy (error 10) says why and what to do.

MOVEA, MOVER, VECTORA and VECTORR load only on an idle axis or behind a linear or blending move
(000:14541-14542, 14628-14629); otherwise the controller reports error 10, whose entry tells the
reader to check AXISMODE and to wait with PAUSE IDLE (000:18543-18547). The run's message names
the keyword and the remedy, instead of the bare number.
"""

from __future__ import annotations

import pytest

from tests.runtime.running import simulate


@pytest.mark.parametrize(
    ("source", "keyword"),
    [
        pytest.param("DRIVEENABLE.0 = 1\nJOG.0 = 10\nMOVER.0 = 100\n", "MOVER", id="mover-while-jogging"),
        pytest.param("DRIVEENABLE.0 = 1\nTORQUE.0 = 10\nMOVEA.0 = 10\n", "MOVEA", id="movea-in-torque-mode"),
        pytest.param(
            "DRIVEENABLE[0,1] = 1\nJOG.1 = 10\nVECTORA[0,1] = 10, 20\n", "VECTORA", id="vectora-on-a-jogging-axis"
        ),
    ],
)
def test_the_message_names_the_move_and_the_wait(source: str, keyword: str) -> None:
    result = simulate(source)
    assert (result.err, result.erl) == (10, 3)
    assert f"{keyword} loads only on an idle axis or behind a linear move" in result.stop.message
    assert "PAUSE IDLE" in result.stop.message
