"""A NextMove axis configured off is idle, as a disabled one is, whatever its encoder does (000:11750);
a servo axis that moves is not (000:11745-11749)."""

from __future__ import annotations

from tests.runtime.running import simulate

OFF = "REM @sim plant 0 velamp 40\nDRIVEENABLE.0 = 0\nCONFIG.0 = _cfOFF\nDRIVEENABLE.0 = 1\n"


def test_an_axis_off_turned_by_its_dac_is_idle() -> None:
    result = simulate(OFF + 'DAC.0 = 10\nWAIT = 50\nPRINT IDLE.0, " ", VEL.0 > 0\n')
    assert result.terminal == "1 1\n"


def test_a_servo_axis_moving_is_not_idle() -> None:
    result = simulate("MOVER.0 = 1000 : GO.0\nWAIT = 10\nPRINT IDLE.0\n")
    assert result.terminal == "0\n"
