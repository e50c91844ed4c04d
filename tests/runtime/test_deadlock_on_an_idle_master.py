"""A move locked to a master that nothing can move any more leaves a blocked program blocked for good.

The v4 guide's flying shear (000:3790-3818) loads six FLY segments on axis 0
following axis 1. The move buffer holds two moves (000:2942), the chain running
counting as one (MP-12), so the third FLY (line 9) waits for the first segment
to end, which takes 200 units of master travel (000:10522-10526). With the
master idle and nothing to move it, that is a deadlock (W-4), not a run to the
time limit. Whatever can still move the master (an event, an input, a host
packet, a move of its own) keeps the run going: the six segments then cover
1200 units on master and slave alike (000:3817).
"""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate

SEGMENTS = ((200, 200), (200, 400), (100, 150), (400, 400), (100, 50), (200, 0))  # (MASTERDISTANCE, FLY)
FLYING_SHEAR = (
    "AXES[0]\nMASTERSOURCE = _msPOS\nMASTERCHANNEL = 1\n"
    + "".join(f"MASTERDISTANCE = {master}\nFLY = {slave} : GO\n" for master, slave in SEGMENTS)
    + 'PAUSE IDLE.0\nPRINT POS.0, " ", POS.1\nEND\n'
)
MOVE_THE_MASTER = "MOVER.1 = 1200 : GO.1\n"


def test_the_guides_flying_shear_with_an_idle_master_is_a_deadlock_at_the_third_fly() -> None:
    result = simulate(FLYING_SHEAR)
    assert (result.stop.reason, result.stop.line, result.stop.statement) == (StopReason.DEADLOCK, 9, "FLY = 150")
    assert "axis 0 on axis 1" in result.stop.message
    assert result.terminal == ""


@pytest.mark.parametrize(
    ("before", "handler"),
    [
        pytest.param("TIMEREVENT = 20\n", "END\n#TIMER\nTIMEREVENT = 0\n" + MOVE_THE_MASTER + "RETURN\n", id="timer"),
        pytest.param(
            "REM @sim input 3 1 at 500\nINPUTMODE = 8\nINPUTPOSTRIGGER = 8\n",
            "END\n#IN3\n" + MOVE_THE_MASTER + "RETURN\n",
            id="scenario-input",
        ),
        pytest.param('REM @sim host write 1 "5" at 500\n', "END\n#COMMS1\n" + MOVE_THE_MASTER + "RETURN\n", id="host"),
    ],
)
def test_an_event_that_moves_the_master_lets_the_segments_run(before: str, handler: str) -> None:
    result = simulate(before + FLYING_SHEAR + handler)
    assert result.stop.reason is StopReason.END
    assert result.terminal == "1200 1200\n"


def test_a_master_moving_on_its_own_lets_the_segments_run() -> None:
    source = FLYING_SHEAR.replace("FLY = 200 : GO\n", "FLY = 200 : MOVER.1 = 1200 : GO[0,1]\n")
    result = simulate("SPEED.1 = 100\n" + source)
    assert result.stop.reason is StopReason.END
    assert result.terminal == "1200 1200\n"


def test_a_follow_on_an_idle_master_waiting_on_an_input_no_one_sets_is_a_deadlock() -> None:
    # nothing is scheduled: no input will come, and the slave moves only with its master
    source = "MASTERSOURCE.0 = _msPOS\nMASTERCHANNEL.0 = 1\nFOLLOW.0 = 1\nPAUSE IN.3 = 1\n"
    result = simulate(source)
    assert (result.stop.reason, result.stop.line) == (StopReason.DEADLOCK, 4)
    # the program waits on the input (000:1114), not on the follower: the message says so and blames no axis
    assert "waits on inputs or variables" in result.stop.message
    assert "axis 0" not in result.stop.message


def test_a_pause_on_an_input_with_no_move_running_says_it_waits_on_inputs() -> None:
    result = simulate("PAUSE IN1 = 1\nPRINT 1\n")
    assert (result.stop.reason, result.stop.line) == (StopReason.DEADLOCK, 1)
    assert "waits on inputs or variables" in result.stop.message


def test_a_follow_whose_master_an_input_will_move_is_no_deadlock() -> None:
    source = (
        "REM @sim input 3 1 at 300\nMASTERSOURCE.0 = _msPOS\nMASTERCHANNEL.0 = 1\nFOLLOW.0 = 1\n"
        "PAUSE IN.3 = 1\nMOVER.1 = 50 : GO.1\nPAUSE IDLE.1\nWAIT = 10\nPRINT POS.0\n"
    )
    result = simulate(source)
    assert (result.stop.reason, result.terminal) == (StopReason.END, "50\n")


def test_a_cam_on_an_idle_master_under_a_program_waiting_on_nothing_else_is_a_deadlock() -> None:
    source = (
        "MASTERSOURCE.0 = _msPOS\nMASTERCHANNEL.0 = 1\nDIM t(3) = 2, 100, 100\nCAMTABLE(0, t, NULL)\n"
        "CAM.0 = 0 : GO.0\nPAUSE IN.3 = 1\n"
    )
    result = simulate(source)
    assert (result.stop.reason, result.stop.line) == (StopReason.DEADLOCK, 6)
    assert "waits on inputs or variables" in result.stop.message and "axis 0" not in result.stop.message


FLY_THEN_PAUSE = (  # the FLY keyword's example (000:10560-10569), the master axis 1
    "MASTERSOURCE = _msPOS\nMASTERCHANNEL = 1\nMASTERDISTANCE = 1000\nFLY = 500 : GO\nFLY = 1000 : GO\n"
    "PAUSE MOVEBUFFERFREE = 1\nOUT.0 = 1\nPRINT POS.0\n"
)


def test_a_pause_on_the_buffer_of_a_fly_waiting_on_an_idle_master_is_a_deadlock() -> None:
    result = simulate(FLY_THEN_PAUSE)
    assert (result.stop.reason, result.stop.line, result.outputs & 1) == (StopReason.DEADLOCK, 6, 0)


def test_a_pause_on_the_buffer_wakes_when_an_event_moves_the_master() -> None:
    # FLY = 500 over 1000 from rest ends at ratio 1 with the slave 500 on (000:3775-3779): a slot is free
    source = "TIMEREVENT = 50\n" + FLY_THEN_PAUSE + "END\n#TIMER\nTIMEREVENT = 0\nMOVER.1 = 1000 : GO.1\nRETURN\n"
    result = simulate(source)
    assert (result.stop.reason, result.terminal, result.outputs & 1) == (StopReason.END, "500\n", 1)


def test_a_pause_on_the_position_of_a_follower_whose_master_stopped_is_a_deadlock() -> None:
    # FOLLOW = 2 behind 50 units of master: the slave stops at 100 and never reaches 1000
    source = (
        "MASTERSOURCE.0 = _msPOS\nMASTERCHANNEL.0 = 1\nFOLLOW.0 = 2\nMOVER.1 = 50 : GO.1\nPAUSE IDLE.1\n"
        "WAIT = 10\nPRINT POS.0\nPAUSE POS.0 > 1000\n"
    )
    result = simulate(source)
    assert (result.stop.reason, result.stop.line, result.terminal) == (StopReason.DEADLOCK, 8, "100\n")
    assert "axis 0 on axis 1" in result.stop.message  # the program reads the follower: the stall is the cause


def test_a_stop_input_that_cancels_the_waiting_move_wakes_the_program() -> None:
    # STOPINPUTMODE 2 cancels the move (a FLY is not ramped: AX-18): IDLE.0 reads 1 from the tick the input comes
    source = (
        "REM @sim input 5 1 at 300\nSTOPINPUT.0 = 5\nSTOPINPUTMODE.0 = 2\nMASTERSOURCE.0 = _msPOS\n"
        "MASTERCHANNEL.0 = 1\nMASTERDISTANCE.0 = 200\nFLY.0 = 100 : GO.0\nPAUSE IDLE.0\nPRINT TIME\n"
    )
    result = simulate(source)
    assert (result.stop.reason, result.terminal) == (StopReason.END, "300\n")
