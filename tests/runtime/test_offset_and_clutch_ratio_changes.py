"""An OFFSET on a FOLLOW cannot be issued while a clutch changes the ratio: in clutch mode during the ramp up
to the ratio or the ramp down to rest, in extended clutch mode while the ratio changes; and in extended clutch
mode the ratio cannot change while an OFFSET is performed (000:14791-14797). Both are refused as a second
OFFSET is, error 10 (runtime/BEHAVIOUR.md, MP-18), and the move goes on.

The master is the slave's own SPEED, 1000 counts/s (_msSPEED, 000:13936-13945): a MASTERDISTANCE of 500
takes 500 ms of master travel, 100 takes 100 ms."""

from __future__ import annotations

from tests.runtime.running import simulate

HANDLER = 'END\n#ONERROR\nPRINT "error ", ERR\nRETURN\n'
SETUP = (
    "MASTERSOURCE.0 = _msSPEED\nSPEED.0 = 1000\nFOLLOWMODE.0 = {mode}\nMASTERDISTANCE.0 = {distance}\nFOLLOW.0 = 1\n"
)


def test_no_offset_during_the_clutch_ramp_up() -> None:
    source = SETUP.format(mode=2, distance=500) + "WAIT = 100\nOFFSET.0 = 10\nPRINT AXISMODE.0\n" + HANDLER
    assert simulate(source).terminal == "error 10\n128\n"  # _mdFOLLOW alone (000:7155)


def test_an_offset_once_the_clutch_has_reached_the_ratio() -> None:
    source = SETUP.format(mode=2, distance=500) + "WAIT = 700\nOFFSET.0 = 10 : GO.0\nWAIT = 4\nPRINT AXISMODE.0\n"
    assert simulate(source + HANDLER).terminal == "192\n"  # _mdFOLLOW + _mdOFFSET (000:7119-7120)


def test_no_offset_during_the_clutch_ramp_down() -> None:
    source = SETUP.format(mode=2, distance=500) + "WAIT = 700\nSTOP.0\nOFFSET.0 = 10\n" + HANDLER
    assert simulate(source).terminal == "error 10\n"


def test_no_offset_while_an_extended_clutch_changes_the_ratio() -> None:
    source = SETUP.format(mode=3, distance=100) + "WAIT = 300\nFOLLOW.0 = 2\nWAIT = 50\nOFFSET.0 = 10\n"
    assert simulate(source + HANDLER).terminal == "error 10\n"


def test_no_ratio_change_while_an_offset_runs_in_extended_clutch_mode() -> None:
    source = SETUP.format(mode=3, distance=100) + "WAIT = 300\nOFFSET.0 = 100 : GO.0\nWAIT = 10\nFOLLOW.0 = 2\n"
    assert simulate(source + 'PRINT "after"\n' + HANDLER).terminal == "error 10\nafter\n"
