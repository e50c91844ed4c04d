"""In Mint v3 a value that has no place to go is "Missing parameter", in ``mint check`` as in the run.

The guide's two examples (001:13097-13109): ``GAIN[1] = 10,20`` gives a value no axis takes, and a
vector move ``VR[0,1] = ,100`` leaves one of its positions out. The values after ``=`` may not
outnumber the axes given (001:990-992), and without brackets those are the default axes, three at
most on a v3 controller (001:972). A circle takes its two centre coordinates and its angle
(``CIRCLEA[axis0,axis1] = <centre0>,<centre1>,<angle>``, 001:6719). A keyword whose format writes one
value (``OUT = <expression>`` 001:10519, ``OUT0 = <expression>`` 001:10611, ``ENABLE = <expr>``
001:7555) has a place for one only: the guide words "Missing parameter" for axes, so a second value
there is its nearest reading, as v4's 2017 is for channel keywords. ``mint check`` numbers the message
as v4 does: 2017 for a value too many, 2001 for a place left empty (000:18909, 19047).
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.runtime.run import run_source
from mintlang.runtime.scenario import Scenario
from mintlang.runtime.scenario.stimulus import DrivesEnabled

ENABLED = Scenario(drives=(DrivesEnabled(),))


@pytest.mark.parametrize(
    ("line", "code", "where"),
    [
        pytest.param("GAIN[1] = 10,20", "E2017", "20", id="001:13104 a value no axis takes"),
        pytest.param("VR[0,1] = ,100", "E2001", "VR[0,1] = ,100", id="001:13108 a vector position left out"),
        pytest.param("VR = ,100", "E2001", "VR = ,100", id="the same on the default axes"),
        pytest.param("VECTORA[0,1,2] = 10,20,", "E2001", "VECTORA[0,1,2] = 10,20,", id="the last left out"),
        pytest.param("SPEED = 10,20,30,40", "E2017", "40", id="001:972 four values, three axes at most"),
        pytest.param("SPEED = ,,,40", "E2017", "40", id="a skipped place counts"),
        pytest.param("CIRCLEA[0,1] = 10,20,90,5", "E2017", "5", id="001:6719 a circle takes three"),
        pytest.param("CIRCLEA[0,1] = 10,,90", "E2001", "CIRCLEA[0,1] = 10,,90", id="001:6719 and each of them"),
        pytest.param("OUT.1 = 1, 0", "E2017", "0", id="001:10519 one output bit, one value"),
        pytest.param("OUT = 2, 0", "E2017", "0", id="001:10519 the whole byte"),
        pytest.param("O1 = 1, 0", "E2017", "0", id="001:10611 OUT1 abbreviated"),
        pytest.param("ENABLE = 1, 0", "E2017", "0", id="001:7555 ENABLE, v4's RELAY"),
    ],
)
def test_the_check_finds_what_the_run_stops_on(line: str, code: str, where: str) -> None:
    source = f"{line}\n"
    found = [(d.code, source[d.span.start : d.span.end]) for d in mintlang.check(source, dialect="v3")]
    assert found == [(code, where)]
    result = run_source(f'{line}\nPRINT "after"\n', dialect="v3", scenario=ENABLED)
    assert result.terminal == "ERROR: Program: Missing parameter at line 1\n"


@pytest.mark.parametrize(
    ("line", "detail"),
    [
        pytest.param("GAIN[1] = 10,20", "2 values for 1 axis", id="001:13104"),
        pytest.param("OUT = 2, 0", "2 values; OUT takes one", id="001:10519"),
    ],
)
def test_the_check_names_the_message_the_v3_controller_prints(line: str, detail: str) -> None:
    # numbered as v4's 2017, "Too many parameters" (000:19047), which the v3 guide calls "Missing parameter"
    # (001:13097-13104): the message names v3's, as "Invalid axis in Mint v3" does beside v4's error 2
    (finding,) = mintlang.check(f"{line}\n", dialect="v3")
    assert finding.message == f"Too many parameters: Missing parameter in Mint v3: {detail}"


def test_nothing_is_written_before_the_error() -> None:
    # the line fails as a whole, as GAIN[1] = 10,20 does: output 1 stays off, where OUT.1 = 1 sets it (001:4358)
    outputs = [run_source(line, dialect="v3").outputs for line in ("OUT.1 = 1, 0\n", "OUT.1 = 1\n")]
    assert outputs == [0, 2]


@pytest.mark.parametrize(
    "line",
    [
        pytest.param("OUT.1 = 1", id="001:4358 one value"),
        pytest.param("OUT = 1;", id="a fill is one value"),
        pytest.param("SPEED = 10,20,30", id="001:972 three values for three axes"),
        pytest.param("VECTORA[0,1,2] = 10,20", id="001:996 fewer values than axes"),
        pytest.param("CIRCLEA = 10,20,90", id="001:6719 a circle's three values"),
    ],
)
def test_what_the_guide_writes_is_no_error(line: str) -> None:
    assert mintlang.check(f"{line}\n", dialect="v3") == []
