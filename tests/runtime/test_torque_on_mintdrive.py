"""TORQUE on MintDrive, which has no blended moves: the axis must be idle or in torque mode, with no
move pending (000:16886-16889); anything else is error 10, action not possible when the axis is in
motion (000:18543), as for JOG (000:12710-12712). NextMove blends into torque from a positional move
(000:16865-16868)."""

from __future__ import annotations

from tests.runtime.running import simulate

REPORT = '#ONERROR\nPRINT "error ", ERR, " axis ", ERRAXIS\nRETURN\n'
BLEND = "SPEED = 100\nMOVEA = 100 : GO\nWAIT = 50\nTORQUE = 10\nPRINT AXISMODE\n"


def test_mintdrive_refuses_to_blend_torque_into_a_positional_move_and_the_move_goes_on() -> None:
    source = BLEND + "PAUSE IDLE\nPRINT POS\nEND\n" + REPORT
    result = simulate(source, controller="mintdrive")
    assert result.terminal == "error 10 axis 0\n2\n100\n"  # AXISMODE 2 (bit 1, _mdLINEAR, 000:7141): the move
    assert result.erl == 4


def test_nextmove_blends_the_same_torque_into_the_move() -> None:
    result = simulate(BLEND + "STOP\nEND\n" + REPORT, controller="nextmove-bx")
    assert result.terminal == "16\n"  # AXISMODE 16 (bit 4, _mdTORQUE, 000:7149): torque control


def test_mintdrive_refuses_torque_while_a_move_is_pending() -> None:
    result = simulate("MOVEA = 100\nTORQUE = 10\nEND\n" + REPORT, controller="mintdrive")
    assert (result.terminal, result.erl) == ("error 10 axis 0\n", 2)


def test_mintdrive_refuses_torque_on_a_jogging_axis() -> None:
    result = simulate("JOG = 10\nWAIT = 100\nTORQUE = 10\nPRINT AXISMODE\nEND\n" + REPORT, controller="mintdrive")
    assert result.terminal == "error 10 axis 0\n4\n"  # still jogging: AXISMODE 4 (bit 2, _mdJOG, 000:7145)


def test_mintdrive_sets_torque_on_an_idle_axis_and_changes_it_in_torque_mode() -> None:
    source = 'TORQUE = 10\nWAIT = 100\nTORQUE = 20\nPRINT AXISMODE, " ", TORQUE\nEND\n' + REPORT
    assert simulate(source, controller="mintdrive").terminal == "16 20\n"
