"""A NextMove axis configured off no longer updates its position: POS holds while the encoder, which
ENCODER still reads, turns (000:15126-15127, 9629-9630, 8454-8455). CONFIG calls DEFAULT, so POS starts
from 0 (000:8481-8483, 9052); a servo axis counts again from the DEFAULT that turning it back on calls."""

from __future__ import annotations

from tests.runtime.running import simulate

OFF = "REM @sim plant 0 velamp 40\nDRIVEENABLE.0 = 0\nCONFIG.0 = _cfOFF\nDRIVEENABLE.0 = 1\n"
TURN = "DAC.0 = 10\nWAIT = 100\nDAC.0 = 0\n"  # 10 % of a 40 counts/s per % amplifier: the encoder turns


def test_the_position_of_an_axis_off_stays_while_its_encoder_turns() -> None:
    result = simulate(OFF + TURN + 'PRINT POS.0, " ", ENCODER.0 > 0\n')
    assert result.terminal == "0 1\n"


def test_a_position_written_on_an_axis_off_stays_as_written() -> None:
    result = simulate(OFF + "POS.0 = 25\n" + TURN + "PRINT POS.0\n")
    assert result.terminal == "25\n"


def test_a_servo_axis_counts_again_from_zero() -> None:
    servo = "DRIVEENABLE.0 = 0\nCONFIG.0 = _cfSERVO\nDRIVEENABLE.0 = 1\nPRINT POS.0\n"
    result = simulate(OFF.replace(" velamp 40", " ideal") + servo + "MOVER.0 = 100 : GO.0\nPAUSE IDLE.0\nPRINT POS.0\n")
    assert result.terminal == "0\n100\n"
