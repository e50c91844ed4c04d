"""JOG on MintDrive, which has no blended moves: the axis must be idle or jogging, with no move
pending (000:12709-12712); anything else is error 10, action not possible when the axis is in motion
(000:18543). NextMove blends into the jog from a positional move (000:12681-12683)."""

from __future__ import annotations

from tests.runtime.running import simulate

REPORT = '#ONERROR\nPRINT "error ", ERR, " axis ", ERRAXIS\nRETURN\n'
BLEND = "SPEED = 100\nMOVEA = 100 : GO\nWAIT = 50\nJOG = 10\nPRINT AXISMODE\n"


def test_mintdrive_refuses_to_blend_a_jog_into_a_positional_move_and_the_move_goes_on() -> None:
    source = BLEND + "PAUSE IDLE\nPRINT POS\nEND\n" + REPORT
    result = simulate(source, controller="mintdrive")
    assert result.terminal == "error 10 axis 0\n2\n100\n"  # AXISMODE 2 (bit 1, _mdLINEAR, 000:7141): the move
    assert result.erl == 4


def test_nextmove_blends_the_same_jog_into_the_move() -> None:
    result = simulate(BLEND + "STOP\nEND\n" + REPORT, controller="nextmove-bx")
    assert result.terminal == "4\n"  # AXISMODE 4 (bit 2, _mdJOG, 000:7145): jogging


def test_mintdrive_refuses_a_jog_while_a_move_is_pending() -> None:
    result = simulate("MOVEA = 100\nJOG = 10\nEND\n" + REPORT, controller="mintdrive")
    assert (result.terminal, result.erl) == ("error 10 axis 0\n", 2)


def test_mintdrive_jogs_an_idle_axis_and_changes_the_speed_of_a_jogging_one() -> None:
    source = "JOG = 10\nWAIT = 100\nJOG = 20\nWAIT = 100\nPRINT AXISMODE\nJOG = 0\nEND\n" + REPORT
    assert simulate(source, controller="mintdrive").terminal == "4\n"
