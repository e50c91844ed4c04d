"""Cam tables: CAMTABLE, CAM modes, CAMINDEX, CAMSTART/CAMEND, STOP and cam errors (spec FG-11..FG-14).

Axis 0 is the master (MOVER on the ideal plant, stopping on segment boundaries); axis 1 runs the cam.
"""

from __future__ import annotations

from tests.runtime.running import simulate

SETUP = "MASTERSOURCE.1 = _msPOS\nMASTERCHANNEL.1 = 0\n"


def lines(terminal: str) -> list[str]:
    return terminal.split()


def master_steps(*distances: int, show: str = "POS.1") -> str:
    return "".join(f"MOVER.0 = {d} : GO.0\nPAUSE IDLE.0\nWAIT = 4\nPRINT {show}\n" for d in distances)


def test_a_relative_cam_moves_each_segment_over_masterdistance() -> None:
    """[000:3853-3857]: MASTERDISTANCE applies to each segment; values are relative without _cmABSOLUTE."""
    source = SETUP + "DIM t(4) = 3, 100, -50, 200\nCAMTABLE(1, t, NULL)\nMASTERDISTANCE.1 = 100\n"
    source += "CAM.1 = 0 : GO.1\nWAIT = 4\nPRINT AXISMODE.1\n" + master_steps(50, 50, 100, 100, 100)
    source += "PRINT AXISMODE.1\nPRINT CAMINDEX.1\n"
    assert lines(simulate(source).terminal) == ["1024", "50", "100", "50", "250", "250", "0", "3"]


def test_a_master_table_gives_each_segment_its_own_distance() -> None:
    source = SETUP + "DIM t(3) = 2, 100, 100\nDIM m(2) = 50, 200\nCAMTABLE(1, t, m)\n"
    source += "CAM.1 = 0 : GO.1\n" + master_steps(25, 25, 100, 100)
    assert lines(simulate(source).terminal) == ["50", "100", "150", "200"]


def test_camindex_counts_the_executing_segment_from_one() -> None:
    source = SETUP + "DIM t(5) = 4, 1, 1, 1, 1\nCAMTABLE(1, t, NULL)\nMASTERDISTANCE.1 = 10\nPRINT CAMINDEX.1\n"
    source += "CAM.1 = 0 : GO.1\n" + master_steps(5, 10, 10, 10, show="CAMINDEX.1")
    assert lines(simulate(source).terminal) == ["0", "1", "2", "3", "4"]


def test_an_absolute_continuous_cam_restarts_each_cycle_from_its_end_position() -> None:
    """_cmABSOLUTE + _cmCONTINUOUS: table values are positions within the cycle, each cycle starting at 0."""
    source = SETUP + "DIM t(4) = 3, 100, 300, 360\nCAMTABLE(1, t, NULL)\nMASTERDISTANCE.1 = 20\n"
    source += "CAM.1 = _cmABSOLUTE + _cmCONTINUOUS : GO.1\n" + master_steps(20, 20, 20, 20, 10)
    assert lines(simulate(source).terminal) == ["100", "300", "360", "460", "560"]


def test_without_interpolation_the_slave_holds_the_segment_position() -> None:
    """_cmNO_INTERPOLATION: the slave is at the segment's value for the whole segment (FG-12 RC)."""
    source = SETUP + "DIM t(3) = 2, 100, 200\nCAMTABLE(1, t, NULL)\nMASTERDISTANCE.1 = 100\n"
    source += "CAM.1 = _cmABSOLUTE + _cmNO_INTERPOLATION : GO.1\n" + master_steps(50, 100, 100)
    assert lines(simulate(source).terminal) == ["100", "200", "200"]


def test_camstart_and_camend_select_part_of_the_table() -> None:
    source = SETUP + "DIM t(5) = 4, 1, 10, 100, 1000\nCAMTABLE(1, t, NULL)\nCAMSTART.1 = 2\nCAMEND.1 = 3\n"
    source += "MASTERDISTANCE.1 = 10\nCAM.1 = 0 : GO.1\n" + master_steps(10, 10, 10) + "PRINT CAMINDEX.1\n"
    assert lines(simulate(source).terminal) == ["10", "110", "110", "3"]


def test_camtable_resets_camstart_and_camend() -> None:
    source = "DIM t(5) = 4, 1, 2, 3, 4\nCAMSTART.1 = 2\nCAMTABLE(1, t, NULL)\nPRINT CAMSTART.1\nPRINT CAMEND.1\n"
    assert lines(simulate(source, until_ms=100).terminal) == ["1", "4"]


def test_stop_lets_a_continuous_cam_finish_its_cycle() -> None:
    """FG-13 RC: STOP finishes the current cycle's end segment, then the axis stops."""
    source = SETUP + "DIM t(3) = 2, 10, 20\nCAMTABLE(1, t, NULL)\nMASTERDISTANCE.1 = 10\n"
    source += "CAM.1 = _cmCONTINUOUS : GO.1\n" + master_steps(30) + "STOP.1\n" + master_steps(5, 5, 100)
    source += "PRINT AXISMODE.1\n"
    assert lines(simulate(source).terminal) == ["40", "50", "60", "60", "0"]


def test_a_master_distance_of_zero_is_axiserror_bit_11() -> None:
    """FG-14: a segment without master distance: bit 11, crash stop, drive disabled."""
    source = SETUP + "DIM t(3) = 2, 10, 20\nDIM m(2) = 10, 0\nCAMTABLE(1, t, m)\n"
    source += "CAM.1 = 0 : GO.1\nMOVER.0 = 20 : GO.0\nPAUSE IDLE.0\n"
    result = simulate(source)
    assert result.axes[1].axiserror & 2048
    assert not result.axes[1].enabled


def test_a_bad_table_is_error_13_when_the_cam_is_loaded() -> None:
    # CAMTABLE only selects the arrays (the manual selects empty ones and fills them later); CAM checks them
    assert simulate('DIM t(3) = 5, 1, 2\nCAMTABLE(1, t, NULL)\nPRINT "selected"\n', until_ms=100).err == -1
    assert simulate("DIM t(3) = 5, 1, 2\nCAMTABLE(1, t, NULL)\nCAM.1 = 0\n", until_ms=100).err == 13
    assert simulate("DIM t(3) = 2, 1, 2\nCAM.1 = 0\n", until_ms=100).err == 13


def test_a_cam_needs_an_idle_axis() -> None:
    source = "DIM t(3) = 2, 1, 2\nCAMTABLE(1, t, NULL)\nJOG.1 = 10\nCAM.1 = 0\n"
    assert simulate(source, until_ms=100).err == 10


def test_cam_takes_every_mode_bit_its_entry_documents_and_nothing_else() -> None:
    """[000:7595-7620]: CAM's bits run up to 5 (_cmRETRIGGER, 32), past the 0 to 15 its table prints; the
    project reads a bit mask as every documented bit (README, decisions), as mint check does. 48 is a mode
    mint-run does not simulate (the fast latch), not error 3; 64 sets a bit CAM lacks, 1.5 selects no mode."""
    selected = "DIM t(3) = 2, 1, 2\nCAMTABLE(1, t, NULL)\n"
    triggered = simulate(selected + "CAM.1 = _cmTRIGGER + _cmRETRIGGER\n", until_ms=100)
    assert triggered.err == -1 and "not simulated" in triggered.stop.message
    assert simulate(selected + "CAM.1 = 64\n", until_ms=100).err == 3
    assert simulate(selected + "CAM.1 = 1.5\n", until_ms=100).err == 3
