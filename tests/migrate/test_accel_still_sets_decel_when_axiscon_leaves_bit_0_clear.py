"""ACCEL keeps its DECEL companion when every AXISCON write is a constant with bit 0 clear.

AXISCON bit 0 switches DECEL on; with it clear, "any write to ACCEL will overwrite the DECEL value with ACCEL"
(001:7203, 001:5662, 001:6027), and ACCELTIME likewise (001:5728). A program that writes AXISCON only to
turn the 3-channel encoder board on (bit 1) or following-error detection off (bit 2, 001:6028-6029) still
has v3's ACCEL setting DECEL, so the write is rewritten as without AXISCON (spec S-ACCEL: "when AXISCON bit
0 is never set"). Where bit 0 is set, or a value is computed (``AXISCON.0 = AXISCON.0 | 01``, 001:7212),
the engineer decides.
"""

from __future__ import annotations

import pytest

from tests.migrate.helpers import flagged, rewritten

DECIDE = "AXISCON is used: decide whether DECEL must follow this write"


def test_constant_writes_without_bit_0_leave_accel_setting_decel() -> None:
    assert rewritten("S-ACCEL", "AXISCON = 0100\nACCEL = 5000\n") == "AXISCON = 0100\nACCEL = 5000 : DECEL = 5000\n"
    assert rewritten("S-ACCEL", "AXISCON[0,1] = ,8;\nAT = 50\n") == "AXISCON[0,1] = ,8;\nAT = 50 : DECELTIME = 50\n"


def test_bit_0_set_leaves_the_decision_to_the_engineer() -> None:
    assert flagged("S-ACCEL", "AXISCON.1 = 011\nACCEL = 5000\n") == [DECIDE]
    assert flagged("S-ACCEL", "AXISCON = ,1\nACCEL = 5000\n") == [DECIDE]


def test_a_computed_value_leaves_the_decision_to_the_engineer() -> None:
    assert flagged("S-ACCEL", "AXISCON.0 = AXISCON.0 | 01\nACCEL = 5000\n") == [DECIDE]


def test_an_axis_whose_bit_0_is_never_set_keeps_accel_setting_decel() -> None:
    # AXISCON.1 = 011 "turns on the DECEL keyword ... for axis 1" (001:6037-6041): on axis 0 ACCEL still
    # overwrites DECEL (001:7203), so that write is rewritten as in a program without AXISCON
    source = "AXISCON.1 = 011\nACCEL.0 = 5000\nAC[0,2] = 10,20\n"
    assert rewritten("S-ACCEL", source) == (
        "AXISCON.1 = 011\nACCEL.0 = 5000 : DECEL.0 = 5000\nAC[0,2] = 10,20 : DECEL[0,2] = 10,20\n"
    )


@pytest.mark.parametrize(
    "source",
    [
        pytest.param("AXISCON.1 = 011\nACCEL.1 = 5000\n", id="the axis named"),
        pytest.param("AXISCON.1 = 011\nACCEL = 5000;\n", id="the default axes include it"),
        pytest.param("AXISCON[a] = 1\nACCEL.0 = 5000\n", id="an axis not known"),
        pytest.param("AXISCON.1 = 1\na = 0\nACCEL[a] = 5000\n", id="an ACCEL axis not known"),
    ],
)
def test_an_accel_write_that_may_reach_an_axis_with_bit_0_set_is_left_to_the_engineer(source: str) -> None:
    assert flagged("S-ACCEL", source) == [DECIDE]
