"""``TRIGGERMODE(axis) = 0`` starts a move as soon as it is loaded into the move buffer (004:56-61): every move
that would otherwise wait for ``GO``, which the v4 guide lists (000:11052-11070) — cams and flying shear
segments as well as the positional and interpolated moves."""

from __future__ import annotations

from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import run_source
from mintlang.runtime.simulation import Limits

_MASTER_MOVES = "SPEED(1) = 5000 : ACCEL(1) = 50000 : DECEL(1) = 50000\nMOVER(1) = {distance} : GO(1)\nPause IDLE(1)\n"


def _terminal(source: str) -> str:
    result = run_source(source, dialect="mintmt", config="RESETALL\n", limits=Limits(until_ms=10_000))
    assert result.stop.reason is StopReason.END, result.stop
    return result.terminal


def test_a_cam_loaded_with_automatic_triggering_follows_its_master_without_go() -> None:
    """An absolute cam takes its table as positions from where the slave starts (000:7580-7582, 7594-7599): the
    master travels two segments of MASTERDISTANCE 100, so the slave stands on the table's second point, 300."""
    source = (
        "Dim c(5) = 4, 100, 300, 250, 500\n"
        "MASTERSOURCE(0) = _msPOS\nMASTERCHANNEL(0) = 1\nMASTERDISTANCE(0) = 100\n"
        "CAMTABLE(0, c, NULL)\n"
        "TRIGGERMODE(0) = 0\n"
        "CAM(0) = _cmABSOLUTE\n" + _MASTER_MOVES.format(distance=200) + "Print POS(0)\n"
    )
    assert _terminal(source) == "300\n"


def test_a_fly_segment_loaded_with_automatic_triggering_runs_without_go() -> None:
    """A FLY segment moves the slave its distance over the master's MASTERDISTANCE (000:10514-10518): 500 over
    the master's 1000."""
    source = (
        "MASTERSOURCE(0) = _msPOS\nMASTERCHANNEL(0) = 1\nMASTERDISTANCE(0) = 1000\n"
        "TRIGGERMODE(0) = 0\n"
        "FLY(0) = 500\n" + _MASTER_MOVES.format(distance=1000) + "Print POS(0)\n"
    )
    assert _terminal(source) == "500\n"


def test_without_automatic_triggering_the_cam_waits_for_go() -> None:
    """The power-up mode waits for GO, as in v4 (000:11052-11058, MT-10): the master's travel moves nothing."""
    source = (
        "Dim c(5) = 4, 100, 300, 250, 500\n"
        "MASTERSOURCE(0) = _msPOS\nMASTERCHANNEL(0) = 1\nMASTERDISTANCE(0) = 100\n"
        "CAMTABLE(0, c, NULL)\n"
        "CAM(0) = _cmABSOLUTE\n" + _MASTER_MOVES.format(distance=200) + "Print POS(0)\n"
    )
    assert _terminal(source) == "0\n"


def test_a_fly_segment_a_clutch_takes_without_go_is_no_move_to_trigger() -> None:
    """In FOLLOWMODE 3 a FLY changes the ratio of the FOLLOW in progress, which needs no GO (000:3628-3645,
    3664-3667): automatic triggering has nothing to start there. The clutch takes the slave to ratio 1 over the
    master's first 1000 (500) and the next 1000 at 1 make 1500; FLY 2000 over 1000 from ratio 1 ends at ratio 3,
    the slave following 2000 over the segment and 3 x 1000 after it: 6500."""
    source = (
        "MASTERSOURCE(0) = _msPOS\nMASTERCHANNEL(0) = 1\nFOLLOWMODE(0) = 3\nMASTERDISTANCE(0) = 1000\n"
        "TRIGGERMODE(0) = 0\nFOLLOW(0) = 1\n"
        + _MASTER_MOVES.format(distance=2000)
        + "Print POS(0)\nFLY(0) = 2000\n"
        + _MASTER_MOVES.format(distance=2000)
        + "Print POS(0)\n"
    )
    assert _terminal(source) == "1500\n6500\n"
