"""The move buffer note's listings run in ``mint-run`` as the note describes them (004, mintlang/MINTMT.md).

Each listing is the corpus file as the note prints it; where the note's text
says what the machine does after the last line, the test waits for the axes
to come to rest (a line added after the listing) and reads the trace.
"""

from __future__ import annotations

import csv
import itertools
import math
import statistics
from pathlib import Path

import pytest

from tests.runtime.invoking import mint_run

CORPUS = Path(__file__).parents[1] / "corpus" / "mintmt"


def _traced(tmp_path: Path, listing: str, then: str) -> list[dict[str, float]]:
    """Run ``listing`` followed by ``then`` on axes 0 and 1, and read the trace it writes."""
    program = tmp_path / "listing.mnt"
    program.write_text((CORPUS / listing).read_text(encoding="utf-8") + then, encoding="utf-8")
    trace = tmp_path / "trace.csv"
    result = mint_run("--dialect", "mintmt", "--drives", "enabled", "--trace", trace, "--trace-axes", "0,1", program)
    assert result.exit_code == 0, result.output
    with trace.open(encoding="utf-8") as rows:
        return [{name: float(value) for name, value in row.items()} for row in csv.DictReader(rows)]


def test_the_feedrate_listing_rounds_its_corners_at_half_the_speed_of_its_straights(tmp_path: Path) -> None:
    # 004:252-276: a square with rounded corners, the straights at FEEDRATE 20, the corners at 10 (units of
    # SCALE 1: counts). Every join is tangent, so one contoured path runs from (0,0) to (5,0). Its length is
    # 20 + 20 + 15 + 20 on the straights and 4 x 5 x pi/2 on the quarter circles: 75 / 20 + 31.416 / 10 =
    # 6.892 s, the ramps at ACCEL 300000 lasting well under a millisecond; the path starts at 2 ms and changes
    # speed at the first profiler tick in each move (MT-15), up to 2 ms after the join.
    rows = _traced(tmp_path, "an00117_l0255_feedrate.mnt", "Pause IDLE(0) And IDLE(1)\n")
    points = [(row["demand.0"], row["demand.1"]) for row in rows]
    corners = ((20.0, 5.0), (20.0, 25.0), (5.0, 25.0), (5.0, 5.0))
    speeds: dict[str, list[float]] = {"corner": [], "straight": []}
    for before, after in itertools.pairwise(points):
        if before == after:
            continue
        on_corner = any(abs(math.dist(point, centre) - 5.0) < 1e-6 for centre in corners for point in (before, after))
        speeds["corner" if on_corner else "straight"].append(math.dist(before, after) * 1000.0)
    assert statistics.median(speeds["corner"]) == pytest.approx(10.0)
    assert statistics.median(speeds["straight"]) == pytest.approx(20.0)
    assert points[-1] == pytest.approx((5.0, 0.0))
    at_rest = next(row["time_ms"] for row in rows if row["time_ms"] > 2 and row["axismode.0"] == 0)
    assert abs(at_rest - (2 + 6891.6)) <= 5
