"""ENCODERSCALE gives ENCODER, ENCODERVEL and FASTENCODER their units; SCALE and POS are independent of it.

The guide: ENCODERSCALE relates counts to user units for ENCODER, which then reads in user units, and
POS keeps SCALE's (000:9731-9735, its example 4096 counts a revolution); its power-up and DEFAULT value is
1 (000:9023, 9727). ENCODERVEL is the encoder's velocity in those units (000:9774-9776); it is measured
over the last servo tick as VEL is (AX-4). The scale affects the range of ENCODER (000:9626-9627): a value
written is in the scaled units. A scale of 0 leaves no unit to divide by: error 3, as SCALE's (a choice,
runtime/BEHAVIOUR.md), in mint check as in mint-run.
"""

from __future__ import annotations

import mintlang
from tests.runtime.running import simulate

HANDLER = 'END\n#ONERROR\nPRINT "ERR ", ERR\nRETURN\n'


def test_encoder_reads_revolutions_while_pos_reads_counts() -> None:
    source = "PRINT ENCODERSCALE.0\nENCODERSCALE.0 = 4096\nMOVER.0 = 8192 : GO.0 : PAUSE IDLE.0\n"
    source += 'PRINT ENCODER.0, " ", POS.0\n'
    assert simulate(source).terminal == "1\n2 8192\n"  # 8192 / 4096


def test_encodervel_reads_the_velocity_in_encoder_units() -> None:
    # JOG 2000 counts/s: 2 counts every 1 ms tick once the ramp (2000 / 300000 s) is over; 2000 / 4000 = 0.5
    source = 'ENCODERSCALE.0 = 4000\nJOG.0 = 2000\nWAIT = 100\nPRINT ENCODERVEL.0, " ", VEL.0\nSTOP.0\n'
    assert simulate(source).terminal == "0.5 2000\n"


def test_a_value_written_to_encoder_is_in_the_scaled_units() -> None:
    # ENCODER = 10 at scale 4 is 40 counts, which scale 1 reads
    source = "ENCODERSCALE.0 = 4\nENCODER.0 = 10\nPRINT ENCODER.0\nENCODERSCALE.0 = 1\nPRINT ENCODER.0\n"
    assert simulate(source).terminal == "10\n40\n"


def test_default_restores_the_scale_of_1() -> None:
    source = "ENCODERSCALE.1 = 360\nDEFAULT.1\nPRINT ENCODERSCALE.1\n"
    assert simulate(source).terminal == "1\n"


def test_a_scale_of_0_is_error_3_in_both_tools() -> None:
    (diagnostic,) = mintlang.check("ENCODERSCALE.0 = 0\n")
    assert diagnostic.code == "E0003"
    assert simulate("ENCODERSCALE.0 = 0\n" + HANDLER).terminal == "ERR 3\n"
