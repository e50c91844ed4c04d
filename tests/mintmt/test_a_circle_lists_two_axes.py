"""A circle moves two axes, ``CIRCLEA[axis0,axis1]`` (000:8148-8152, 8205-8215): three listed is error 2017, too
many parameters (000:19047-19052). MintMT lists axes in round brackets (``CIRCLEA(0,1,2)``) and reads the keyword
as v4 does (MT-1), so it is the same error there. ``mint check`` reports it at the list and ``mint-run`` raises
it when the line runs, before anything is loaded.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.run import run_source
from mintlang.runtime.scenario import DrivesEnabled, Scenario
from tests.analysis.placed import placed

_ENABLED = Scenario(drives=(DrivesEnabled(),))


@pytest.mark.parametrize(
    ("dialect", "source"),
    [
        pytest.param("mintmt", "CIRCLEA(0,1,2) = 10, 0, 90\nGO(0,1)\n", id="MintMT CIRCLEA(0,1,2)"),
        pytest.param("mintmt", "CIRCLER([0,1,2]) = 10, 0, 90\nGO(0,1)\n", id="MintMT CIRCLER([0,1,2])"),
        pytest.param("v4", "CIRCLEA[0,1,2] = 10, 0, 90\nGO[0,1]\n", id="v4 CIRCLEA[0,1,2]"),
        pytest.param("v4", "DIM j = 2\nCIRCLER[0,1,j] = 10, 0, 90\nGO[0,1]\n", id="v4 an axis in a variable"),
    ],
)
def test_three_axes_are_too_many_in_the_check_and_the_run(dialect: str, source: str) -> None:
    line = source.count("\n", 0, source.index("CIRCLE")) + 1
    assert placed(source, "code", "line", codes="E", dialect=dialect) == [("E2017", line)]
    result = run_source(source, dialect=dialect, scenario=_ENABLED)
    assert (result.err, result.erl) == (2017, line)
    assert [axis.pos for axis in result.axes[:3]] == [0, 0, 0]


def test_two_axes_listed_make_the_circle() -> None:
    """Centre (10, 0) a quarter turn anticlockwise from (0, 0): the arc ends at (10, -10) (000:8166-8168)."""
    result = run_source("CIRCLEA(0,1) = 10, 0, 90\nGO(0,1)\nPause IDLE(0)\n", dialect="mintmt", scenario=_ENABLED)
    assert result.err == -1
    assert [round(axis.pos, 6) for axis in result.axes[:2]] == [10, -10]


def test_mint_v3_is_left_as_its_checker_reads_it() -> None:
    """The v3 guide asks a circle for at least two axes (001:3257) and says nothing of a third: v3's checker
    reports none, and its run does not stop on one."""
    source = "CIRCLEA[0,1,2] = 10,0,90 : GO\nPAUSE IDLE.0\n"
    assert placed(source, "code", codes="E", dialect="v3") == []
    result = run_source(source, dialect="v3", controller="euroservo", scenario=_ENABLED)
    assert (result.err, result.stop.reason.value) == (-1, "end")
