"""The stop input in each STOPINPUTMODE (spec AX-17, AX-18, EV-8)."""

from __future__ import annotations

from tests.runtime.running import simulate

HANDLER = 'END\n#STOP\nPRINT "stop at ", TIME, " vel ", VEL.0\nRETURN\n'


def program(mode: int, body: str) -> str:
    return f"STOPINPUT.0 = 3 : STOPINPUTMODE.0 = {mode} : ERRORDECEL.0 = 100000\n{body}" + HANDLER


def test_normal_mode_ramps_to_rest_calls_stop_and_resumes_the_move_when_the_input_clears() -> None:
    source = program(1, 'MOVER.0 = 8000 : GO.0\nPAUSE IDLE.0\nPRINT "done at ", POS.0, " ", TIME\n')
    result = simulate(source + "REM @sim input 3 1 at 100\nREM @sim input 3 0 at 400\n")
    first, second = result.terminal.splitlines()
    assert first.startswith("stop at ") and first.endswith(" vel 0")
    assert 300 < int(first.split()[2]) < 400  # 20000 counts/s ramped down at 100000 counts/s² takes 200 ms
    assert second.startswith("done at 8000 ")
    assert int(second.split()[3]) > 700  # later than the uninterrupted move


def test_normal_mode_does_not_call_stop_when_the_input_clears_before_rest() -> None:
    source = program(1, 'MOVER.0 = 8000 : GO.0\nPAUSE IDLE.0\nPRINT "done at ", POS.0\n')
    result = simulate(source + "REM @sim input 3 1 at 100\nREM @sim input 3 0 at 150\n")
    assert result.terminal == "done at 8000\n"


def test_stop_mode_ramps_down_and_clears_the_move() -> None:
    source = program(3, 'MOVER.0 = 8000 : GO.0\nWAIT = 700\nPRINT POS.0, " ", AXISMODE.0\n')
    result = simulate(source + "REM @sim input 3 1 at 100\nREM @sim input 3 0 at 400\n")
    stop, final = result.terminal.splitlines()
    assert stop.startswith("stop at ")
    position, mode = final.split()
    assert int(position) < 8000 and mode == "0"


def test_cancel_mode_crash_stops_and_calls_stop_at_once() -> None:
    source = program(2, "MOVER.0 = 8000 : GO.0\nWAIT = 300\nPRINT POS.0\n")
    result = simulate(source + "REM @sim input 3 1 at 100\n")
    stop, _ = result.terminal.splitlines()
    assert stop.startswith("stop at 10")


def test_ignore_mode_only_calls_stop_and_the_move_goes_on() -> None:
    source = program(0, 'MOVER.0 = 8000 : GO.0\nPAUSE IDLE.0\nPRINT POS.0, " ", AXISSTATUS.0\n')
    result = simulate(source + "REM @sim input 3 1 at 100\n")
    assert result.terminal.splitlines()[-1] == "8000 64"  # still shown by AXISSTATUS bit 6


def test_a_stop_command_while_held_ends_the_held_move() -> None:
    source = program(1, 'MOVER.0 = 8000 : GO.0\nWAIT = 500\nSTOP.0\nPAUSE IDLE.0\nPRINT "idle ", AXISMODE.0\n')
    result = simulate(source + "REM @sim input 3 1 at 100\n")
    assert result.terminal.splitlines()[-1] == "idle 0"


def test_an_errordecel_of_zero_stops_at_once_instead_of_ramping_for_ever() -> None:
    # 000:9991: ERRORDECEL takes 0; a rate of 0 cannot ramp down, so the axis stops where it is
    source = "ERRORDECEL.0 = 0\nSTOPINPUT.0 = 2\nSTOPINPUTMODE.0 = 1\n"
    source += "REM @sim input 2 1 at 100\nJOG.0 = 1000\nWAIT = 300\n"
    result = simulate(source + "PRINT VEL.0\n")
    assert result.terminal == "0\n"


def test_a_move_held_at_rest_still_has_its_distance_to_go() -> None:
    # 000:15198-15201: POSREMAINING is what is left of the current move, and in mode 1 the held move stays current
    source = program(1, 'MOVER.0 = 8000 : GO.0\nWAIT = 350\nPRINT POS.0, " ", POSREMAINING.0, " ", IDLE.0\n')
    result = simulate(source + "REM @sim input 3 1 at 100\n")
    position, remaining, idle = (float(word) for word in result.terminal.splitlines()[-1].split())
    assert idle == 0 and remaining > 1000  # ramped down from below 20000 counts/s: at rest well short of 8000
    assert abs(position + remaining - 8000) <= 0.5  # POS reads the encoder, the demand rounded to a count
