"""FOLLOW in its four FOLLOWMODEs, master selection and STOP (spec FG-1..FG-6).

Axis 0 is the master, moved with MOVER or JOG on the ideal plant; axis 1 follows.
"""

from __future__ import annotations

from tests.runtime.running import simulate

SETUP = "MASTERSOURCE.1 = _msPOS\nMASTERCHANNEL.1 = 0\n"


def lines(terminal: str) -> list[str]:
    return terminal.split()


def master_steps(*distances: int) -> str:
    return "".join(f"MOVER.0 = {d} : GO.0\nPAUSE IDLE.0\nWAIT = 4\nPRINT POS.1\n" for d in distances)


def test_ratio_two_gives_exactly_twice_the_master_travel() -> None:
    """Mode 0 is position locked: slave = start + 2 x master travel, in counts, with no GO (FG-3)."""
    source = SETUP + "FOLLOW.1 = 2\nPRINT AXISMODE.1\n" + master_steps(1000, -333)
    assert lines(simulate(source).terminal) == ["128", "2000", "1334"]


def test_ratio_changes_are_instant_and_follow_zero_keeps_following() -> None:
    source = SETUP + "FOLLOW.1 = 1\n" + master_steps(100)
    source += "FOLLOW.1 = -0.25\n" + master_steps(400) + "FOLLOW.1 = 0\n" + master_steps(100)
    source += "PRINT AXISMODE.1\nPRINT FOLLOW.1\n"
    assert lines(simulate(source).terminal) == ["100", "0", "0", "128", "0"]


def test_followdenom_divides_the_next_follow() -> None:
    """FOLLOWDENOM 10, FOLLOW 11: ratio 1.1 (FG-3); MintDrive has the keyword, with a virtual master."""
    source = "MASTERSOURCE.0 = _msSPEED\nSPEED.0 = 1000\nFOLLOWDENOM.0 = 10\nFOLLOW.0 = 11\nWAIT = 1000\n"
    source += "STOP.0\nPRINT FOLLOW.0\nPRINT FOLLOWDENOM.0\nPRINT POS.0\n"
    ratio, denominator, position = lines(simulate(source, controller="mintdrive").terminal)
    assert (ratio, denominator) == ("11", "10")
    assert abs(float(position) - 1100) <= 5


def test_master_position_is_converted_into_the_slave_units() -> None:
    """Master SCALE 2000, slave SCALE 4000: two master revolutions give two slave revolutions (FG-1)."""
    source = SETUP + "SCALE.0 = 2000\nSCALE.1 = 4000\nFOLLOW.1 = 1\n" + master_steps(2)
    source += "PRINT ENCODER.1\n"
    assert lines(simulate(source).terminal) == ["2", "8000"]


def test_a_virtual_master_runs_at_speed_from_zero() -> None:
    """_msSPEED: the master is SPEED on the master channel, by default the slave itself (FG-1)."""
    source = "MASTERSOURCE.1 = _msSPEED\nPRINT MASTERCHANNEL.1\nSPEED.1 = 1000\nFOLLOW.1 = 2\nWAIT = 500\n"
    source += "STOP.1\nWAIT = 4\nPRINT POS.1\n"
    result = simulate(source)
    first, position = lines(result.terminal)
    assert first == "1"
    assert 996 <= float(position) <= 1004


def test_following_yourself_is_error_70() -> None:
    """[000:18757-18761]: MASTERCHANNEL = 0 : FOLLOW.0 = 1."""
    result = simulate("MASTERCHANNEL.0 = 0\nFOLLOW.0 = 1\n", until_ms=100)
    assert result.err == 70


def test_writing_mastersource_resets_masterchannel() -> None:
    source = "MASTERCHANNEL.1 = 3\nPRINT MASTERCHANNEL.1\nMASTERSOURCE.1 = _msENCODER\nPRINT MASTERCHANNEL.1\n"
    assert lines(simulate(source, until_ms=100).terminal) == ["3", "0"]


def test_followmode_cannot_change_while_following() -> None:
    result = simulate(SETUP + "FOLLOW.1 = 1\nFOLLOWMODE.1 = 1\n", until_ms=100)
    assert result.err == 10


def test_velocity_lock_slips_while_the_slave_ramps_at_its_accel() -> None:
    """Mode 1: master jumps to 1000 counts/s; the slave takes 1 s at ACCEL 1000 and loses 500 counts (FG-4)."""
    source = SETUP + "FOLLOWMODE.1 = 1\nACCEL.1 = 1000\nDECEL.1 = 1000\nFOLLOW.1 = 1\nWAIT = 10\n"
    source += "ACCEL.0 = 8000000\nJOG.0 = 1000\nWAIT = 2000\nPRINT POS.0 - POS.1\nSTOP.1\n"
    source += "PAUSE AXISMODE.1 = 0\nPRINT VEL.1\n"
    first, speed = lines(simulate(source).terminal)
    assert 498 <= float(first) <= 504
    assert speed == "0"


def test_clutch_mode_loses_half_the_clutch_distance_each_way() -> None:
    """Mode 2 [000:3613-3614]: ramp in and out over MASTERDISTANCE 100 at ratio 1 lose 50 each."""
    source = SETUP + "FOLLOWMODE.1 = 2\nMASTERDISTANCE.1 = 100\nFOLLOW.1 = 1\n" + master_steps(40, 60, 900)
    source += "STOP.1\n" + master_steps(100, 100) + "PRINT AXISMODE.1\n"
    assert lines(simulate(source).terminal) == ["8", "50", "950", "1000", "1000", "0"]


def test_continuous_clutch_ratio_change_equals_the_fly_of_the_manual() -> None:
    """Mode 3 (FG-5): ratio 1 -> 3 over 20 moves the slave FLY = (1+3)/2 x 20 = 40, then holds 3:1."""
    source = SETUP + "FOLLOWMODE.1 = 3\nMASTERDISTANCE.1 = 20\nFOLLOW.1 = 1\n" + master_steps(20, 80)
    source += "FOLLOW.1 = 3\n" + master_steps(20, 10)
    assert lines(simulate(source).terminal) == ["10", "90", "130", "160"]


def test_continuous_clutch_accepts_fly_without_go() -> None:
    """Mode 3 (FG-5): at ratio 0.5 with MASTERDISTANCE 8, FLY = 6 reaches 1:1 [000:3694-3699]."""
    source = SETUP + "FOLLOWMODE.1 = 3\nMASTERDISTANCE.1 = 8\nFOLLOW.1 = 0.5\n" + master_steps(8, 8)
    source += "FLY.1 = 6\n" + master_steps(8, 8) + "MASTERDISTANCE.1 = 10\nSTOP.1\n" + master_steps(10, 10)
    source += "PRINT AXISMODE.1\n"
    assert lines(simulate(source).terminal) == ["2", "6", "12", "20", "25", "25", "0"]


def test_continuous_clutch_stop_waits_for_the_queued_segments() -> None:
    """The manual's 'keep at 1:1 for 1000 master revs before stopping' example [000:3730-3740]."""
    source = SETUP + "FOLLOWMODE.1 = 3\nMASTERDISTANCE.1 = 10\nFOLLOW.1 = 1\nMASTERDISTANCE.1 = 1000\n"
    source += "FLY.1 = 1000\nMASTERDISTANCE.1 = 10\nSTOP.1\n" + master_steps(1010, 10, 10) + "PRINT AXISMODE.1\n"
    assert lines(simulate(source).terminal) == ["1005", "1010", "1010", "0"]


def test_stop_in_mode_0_is_instant() -> None:
    source = SETUP + "FOLLOW.1 = 1\n" + master_steps(100) + "STOP.1\nPRINT AXISMODE.1\n" + master_steps(100)
    assert lines(simulate(source).terminal) == ["100", "0", "100"]
