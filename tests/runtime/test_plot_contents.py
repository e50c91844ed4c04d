"""What ``mint-run --plot`` draws: the axes that moved, their units, the I/O that switched, no rounding noise."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

from mintlang.runtime.run import run_source
from mintlang.runtime.scenario import Scenario
from mintlang.runtime.scenario.stimulus import DrivesEnabled
from mintlang.runtime.simulation import Limits
from mintlang.runtime.trace import Trace

# Axis 1 moves 20 user units at SCALE 4000 (80000 counts); OUT.2 is on during the move, OUT.0 comes on after it.
PROGRAM = """SCALE.1 = 4000
SPEED.1 = 10 : ACCEL.1 = 100 : DECEL.1 = 100
OUT.2 = 1
MOVER.1 = 20 : GO.1
PAUSE IDLE.1
OUT.2 = 0
OUT.0 = 1
"""


def _traced(*, chosen: bool) -> Trace:
    trace = Trace((0, 1, 2, 3), None, plotting=True, chosen=chosen)
    run_source(
        PROGRAM,
        scenario=Scenario(drives=(DrivesEnabled(),)),
        limits=Limits(every_tick=True),
        on_tick=trace.record,
    )
    return trace


def test_only_the_axes_that_moved_are_drawn_unless_the_axes_were_chosen() -> None:
    assert _traced(chosen=False).moved() == (1,)
    assert _traced(chosen=True).moved() == (0, 1, 2, 3)


def test_the_io_lanes_hold_the_outputs_that_switched_and_when() -> None:
    trace = _traced(chosen=False)
    assert trace.io["OUT"].bits() == [0, 2]
    assert trace.io["IN"].bits() == []
    # on at once; off when the move ends (T = 20/10 + 10/100 = 2.1 s from profiler tick 2), OUT.0 on then
    # the move ends at 2102 (2 ms + 2.1 s); its demand was 0.8 count short at 2100, so VEL, over 2 ms, is 0 at 2103
    assert trace.io["OUT"].points == [(0.0, 4), (2103.0, 1)]


def test_following_error_within_half_a_count_is_drawn_as_zero_on_an_ideal_drive() -> None:
    trace = _traced(chosen=False)
    assert set(trace.plotted[1, "folerror"].points()[1]) == {0.0}
    assert trace.scales[1] == 4000.0


@pytest.mark.skipif(importlib.util.find_spec("matplotlib") is None, reason="no plot extra")
def test_the_plot_is_written(tmp_path: Path) -> None:
    path = tmp_path / "run.png"
    _traced(chosen=False).plot(path, "run.mnt on NextMove PCI")
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_each_panel_names_its_units_and_mixed_scales_say_so() -> None:
    trace = _traced(chosen=True)  # axis 1 at SCALE 4000, the others at 1
    assert trace.units((1,), per_second=False) == "user units"
    assert trace.units((1,), per_second=True) == "user units/s"
    assert trace.units((0,), per_second=True) == "counts/s"
    assert trace.units((0, 1), per_second=False) == "user units; counts at SCALE 1"
