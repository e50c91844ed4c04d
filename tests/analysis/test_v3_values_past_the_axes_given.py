"""In Mint v3 more values than the axes given is an error in mint check as in mint-run.

The values after the equal sign may not outnumber the axes given, but for CIRCLEA and CIRCLER:
``MOVEA[0,1] = 100,150,500`` is invalid, ``MOVEA[0,1,2] = 10,20`` valid (001:990-998). The v3 guide files
``GAIN[1] = 10,20`` under "Missing parameter": no axis is given for the 20 (001:13097-13111). A dot names one
axis as ``[1]`` does (001:649-659). mint check reports it as the run's error 2017 at the first value past the
axes; the v3 run ends with ``ERROR: Program: Missing parameter at line 1``. Columns are counted by hand from 1.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.run import run_source
from mintlang.runtime.scenario import Scenario
from mintlang.runtime.scenario.stimulus import DrivesEnabled
from tests.analysis.placed import placed_codes

_PAST = [
    pytest.param("GAIN[1] = 10,20\n", 14, id="001:13103 no axis for the 20"),
    pytest.param("MOVEA[0,1] = 100,150,500\n", 22, id="001:992 three values for two axes"),
    pytest.param("SCALE[0] = 4000, 2.5\n", 18, id="two values for one axis in brackets"),
    pytest.param("SPEED.1 = 10, 20\n", 15, id="two values for the one axis of a dot"),
]


@pytest.mark.parametrize(("source", "column"), _PAST)
def test_mint_check_reports_the_first_value_past_the_axes(source: str, column: int) -> None:
    assert placed_codes(source, "v3") == [("E2017", 1, column)]


@pytest.mark.parametrize(("source", "column"), _PAST)
def test_the_v3_run_ends_with_missing_parameter(source: str, column: int) -> None:
    result = run_source(source, dialect="v3", scenario=Scenario(drives=(DrivesEnabled(),)))
    assert result.terminal == "ERROR: Program: Missing parameter at line 1\n"


@pytest.mark.parametrize(
    "source",
    [
        pytest.param("MOVEA[0,1,2] = 10,20\n", id="001:996 fewer values than axes"),
        pytest.param("SPEED[0,1] = 10,20\n", id="001:675 one value for each axis"),
        pytest.param("CIRCLEA[0,1] = 10,10,90\n", id="001:990, 3361 a circle's three values on two axes"),
    ],
)
def test_values_the_axes_take_are_not_reported(source: str) -> None:
    assert placed_codes(source, "v3") == []
