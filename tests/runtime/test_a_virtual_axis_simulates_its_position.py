"""A virtual axis (CONFIG = _cfVIRTUAL, NextMove) executes moves without any physical output and simulates
its position (000:8442, 8456-8458): its DAC stays at 0 and POS reaches the target whatever the motor does.
Configured a servo again, it counts the encoder from there: CONFIG calls DEFAULT, so POS starts at 0
(000:8481-8483, 9052)."""

from __future__ import annotations

from tests.runtime.running import simulate

VIRTUAL = "DRIVEENABLE.0 = 0\nCONFIG.0 = _cfVIRTUAL\nDRIVEENABLE.0 = 1\nKPROP.0 = 1\n"
MOVE = 'MOVER.0 = 100 : GO.0\nWAIT = 20\nPRINT DAC.0\nPAUSE IDLE.0\nPRINT POS.0, " ", DAC.0\n'


def test_a_virtual_axis_on_a_jammed_motor_reaches_its_target_with_no_output() -> None:
    assert simulate("REM @sim plant 0 stalled\n" + VIRTUAL + MOVE).terminal == "0\n100 0\n"


def test_a_virtual_axis_on_a_velocity_amplifier_drives_nothing() -> None:
    assert simulate("REM @sim plant 0 velamp 100\n" + VIRTUAL + MOVE).terminal == "0\n100 0\n"


def test_a_servo_again_counts_the_motor_which_did_not_move() -> None:
    servo = "DRIVEENABLE.0 = 0\nCONFIG.0 = _cfSERVO\nDRIVEENABLE.0 = 1\nMOVER.0 = 10 : GO.0\nWAIT = 50\nPRINT POS.0\n"
    assert simulate("REM @sim plant 0 stalled\n" + VIRTUAL + MOVE + servo).terminal == "0\n100 0\n0\n"
