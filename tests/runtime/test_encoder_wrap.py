"""ENCODERWRAP makes ENCODER read within one turn; 0 turns the wrap off.

The guide: with ``ENCODERWRAP.0 = 4096`` the ENCODER keyword reads 0 to 4095, the
value wraps at the ENCODERWRAP value, and a wrap of 0 returns the full range
(000:9811-9826). Its power-up and DEFAULT value is 0 (000:9006, 9024, the DEFAULT
table), and its range 0.0 to 8388607.0 (000:9811): outside it is error 3. POS does
not wrap with it: ENCODERWRAP is the ENCODER keyword's.
"""

from __future__ import annotations

from tests.runtime.running import simulate

HANDLER = 'END\n#ONERROR\nPRINT "ERR ", ERR\nRETURN\n'


def test_encoder_reads_within_the_wrap_and_pos_does_not() -> None:
    source = 'ENCODERWRAP.0 = 4096\nMOVER.0 = 5000 : GO.0 : PAUSE IDLE.0\nPRINT ENCODER.0, " ", POS.0\n'
    assert simulate(source).terminal == "904 5000\n"  # 5000 - 4096


def test_a_move_backwards_past_zero_reads_from_the_top_of_the_wrap() -> None:
    source = "ENCODERWRAP.0 = 4096\nMOVER.0 = -100 : GO.0 : PAUSE IDLE.0\nPRINT ENCODER.0\n"
    assert simulate(source).terminal == "3996\n"  # -100 + 4096


def test_a_wrap_of_0_turns_the_wrap_off() -> None:
    source = "ENCODERWRAP.0 = 4096\nMOVER.0 = 5000 : GO.0 : PAUSE IDLE.0\nENCODERWRAP.0 = 0\nPRINT ENCODER.0\n"
    assert simulate(source).terminal == "5000\n"


def test_the_wrap_reads_back_and_default_clears_it() -> None:
    source = 'ENCODERWRAP.1 = 360\nPRINT ENCODERWRAP.1, " ", ENCODERWRAP.0\nDEFAULT.1\nPRINT ENCODERWRAP.1\n'
    assert simulate(source).terminal == "360 0\n0\n"


def test_a_negative_wrap_is_error_3() -> None:
    assert simulate("ENCODERWRAP.0 = -1\n" + HANDLER).terminal == "ERR 3\n"
