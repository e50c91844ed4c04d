"""FLY: flying-shear segments over MASTERDISTANCE, blended while loaded, crash stop when none is left (FG-8, FG-9).

The master is axis 0 driven by MOVER on the ideal plant, so it stops exactly
on segment boundaries and each printed slave position is exact.
"""

from __future__ import annotations

from tests.runtime.running import simulate


def lines(terminal: str) -> list[str]:
    return terminal.split()


SETUP = """
MASTERSOURCE.1 = _msPOS
MASTERCHANNEL.1 = 0
MOVEBUFFERSIZE.1 = 8
"""


def master_steps(*distances: int) -> str:
    """Move the master by each distance and print the slave position after each."""
    return "".join(f"MOVER.0 = {d} : GO.0\nPAUSE IDLE.0\nWAIT = 4\nPRINT POS.1\n" for d in distances)


def test_the_manual_worked_example_covers_1200_on_master_and_slave() -> None:
    """FG-9 [000:3802-3818]: 0->2:1, 2:1 held, ->1:1, 1:1 held, ->0, dwell."""
    source = (
        SETUP
        + """
MASTERDISTANCE.1 = 200 : FLY.1 = 200 : GO.1
MASTERDISTANCE.1 = 200 : FLY.1 = 400 : GO.1
MASTERDISTANCE.1 = 100 : FLY.1 = 150 : GO.1
MASTERDISTANCE.1 = 400 : FLY.1 = 400 : GO.1
MASTERDISTANCE.1 = 100 : FLY.1 = 50 : GO.1
MASTERDISTANCE.1 = 200 : FLY.1 = 0 : GO.1
WAIT = 4
PRINT AXISMODE.1
"""
        + master_steps(200, 200, 100, 400, 100, 200)
        + "PRINT POS.0\nPRINT AXISMODE.1\n"
    )
    result = simulate(source)
    assert lines(result.terminal) == ["512", "200", "600", "750", "1150", "1200", "1200", "1200", "0"]


def test_a_segment_accelerates_at_constant_rate_against_the_master() -> None:
    """From rest, FLY = MASTERDISTANCE/2 reaches ratio 1; halfway the slave has covered a quarter of it."""
    source = SETUP + "MASTERDISTANCE.1 = 400 : FLY.1 = 200 : GO.1\n" + master_steps(200, 200)
    assert lines(simulate(source).terminal) == ["50", "200"]


def test_segments_blend_when_loaded_and_the_axis_crash_stops_when_none_is_left() -> None:
    """After 1:1 is reached a second segment holds it; with nothing loaded after it the slave stops dead."""
    source = (
        SETUP
        + """
MASTERDISTANCE.1 = 100 : FLY.1 = 50 : GO.1
FLY.1 = 100 : GO.1
PRINT MOVEBUFFERFREE.1
JOG.0 = 1000
PAUSE POS.0 >= 400
JOG.0 = 0
PAUSE IDLE.0
WAIT = 4
PRINT POS.1
PRINT AXISMODE.1
"""
    )
    assert lines(simulate(source).terminal) == ["6", "150", "0"]


def test_fly_zero_dwells_for_the_master_distance() -> None:
    source = SETUP + "MASTERDISTANCE.1 = 300 : FLY.1 = 0 : GO.1\n" + master_steps(150) + "PRINT AXISMODE.1\n"
    source += master_steps(150) + "PRINT AXISMODE.1\n"
    assert lines(simulate(source).terminal) == ["0", "512", "0", "0"]


def test_stop_decelerates_over_masterdistance_from_the_current_ratio() -> None:
    """MP-22: at ratio 1, STOP with MASTERDISTANCE 100 ramps down while the slave covers half of it."""
    source = (
        SETUP
        + """
MASTERDISTANCE.1 = 100 : FLY.1 = 50 : GO.1
MASTERDISTANCE.1 = 1000 : FLY.1 = 1000 : GO.1
"""
        + master_steps(300)
        + "MASTERDISTANCE.1 = 100\nSTOP.1\n"
        + master_steps(100)
        + "PRINT AXISMODE.1\n"
    )
    assert lines(simulate(source).terminal) == ["250", "300", "0"]


def test_fly_loads_only_behind_fly_segments() -> None:
    source = SETUP + "JOG.1 = 10\nFLY.1 = 10\n"
    result = simulate(source, until_ms=100)
    assert result.err == 10
