"""A MintMT keyword with an index after its axes takes no more values than it has axes (000:572-576): more is
error 2017, before anything is written, when the line runs as in ``mint check`` — as for any axis keyword
(runtime/BEHAVIOUR.md, NM-10). The indices (004:232, 295-299) are no values."""

from __future__ import annotations

import pytest

from mintlang.runtime.run import run_source
from tests.analysis.placed import placed_codes


@pytest.mark.parametrize(
    "line",
    [
        pytest.param("CONTOURPARAMETER([0,1],0) = 10, 20, 30", id="contourparameter-three-values-two-axes"),
        pytest.param("MOVEOUT(0,0) = 7, 1", id="moveout-two-values-one-axis"),
        pytest.param("MOVEOUTX(0,1) = 0, 1", id="moveoutx-two-values-one-axis"),
        pytest.param("MOVEPULSEOUTX(0,3) = 100, 200", id="movepulseoutx-two-values-one-axis"),
    ],
)
def test_the_run_stops_on_2017_where_mint_check_reports_it(line: str) -> None:
    source = f"REM @sim drives enabled\nMOVEBUFFERSIZE(0) = 4\n{line}\n"
    assert [code for code, _, _ in placed_codes(source, "mintmt")] == ["E2017"]
    result = run_source(source, dialect="mintmt")
    assert (result.err, result.erl, result.stop.line) == (2017, 3, 3)


def test_as_many_values_as_axes_are_written() -> None:
    # the note's threshold for both axes, one value each (004:232)
    source = 'CONTOURPARAMETER([0,1],0) = 10, 20\nPrint CONTOURANGLE(0), " ", CONTOURANGLE(1)\n'
    assert run_source(source, dialect="mintmt").terminal == "10 20\n"
