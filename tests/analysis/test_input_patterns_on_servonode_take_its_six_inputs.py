"""On ServoNode 51 a bit pattern of the digital inputs past its six inputs is error 3 in mint check as in mint-run.

INPUTMODE, INPUTACTIVELEVEL, INPUTPOSTRIGGER and INPUTNEGTRIGGER take a bitmap of the digital inputs
(000:12315-12316, 000:12293); their tables print no ServoNode 51 row, and every row they print is the pattern of all
the controller's inputs: NextMove PCI's 20 inputs 1048575, NextMove PC's 24 16777215, NextMove BX's 16 65535,
MintDrive's 18 262143 (000:11928-11931; 000:12281-12285, 12336-12340, 12400-12404, 12454-12458). ServoNode 51 has
6 (000:11932): 0 to 63, 2^6 - 1; a value "outside of the accepted range of values" is #3 (000:18518-18521).
Columns are the value's, counted by hand from 1.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate


def _errors(source: str) -> list[tuple[str, int]]:
    index = mintlang.LineIndex(source)
    found = mintlang.check(source, controller="servonode51")
    return [(d.code, index.position(d.span.start).column) for d in found if d.code.startswith("E")]


@pytest.mark.parametrize(
    ("source", "column"),
    [
        pytest.param("INPUTMODE = 64\n", 13, id="INPUTMODE"),
        pytest.param("INPUTACTIVELEVEL = 127\n", 20, id="INPUTACTIVELEVEL"),
        pytest.param("INPUTPOSTRIGGER = 65535\n", 19, id="INPUTPOSTRIGGER"),
        pytest.param("INPUTNEGTRIGGER = -1\n", 19, id="INPUTNEGTRIGGER"),
    ],
)
def test_a_pattern_past_the_sixth_input_is_error_3_in_both_tools(source: str, column: int) -> None:
    assert _errors(source) == [("E0003", column)]
    result = simulate(source, controller="servonode51")
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 3, 1)


@pytest.mark.parametrize("source", ["INPUTMODE = 63\n", "INPUTACTIVELEVEL = 0\n", "INPUTPOSTRIGGER = 0x20\n"])
def test_a_pattern_of_its_six_inputs_passes_both_tools(source: str) -> None:
    assert _errors(source) == []
    assert simulate(source, controller="servonode51").stop.reason is StopReason.END
