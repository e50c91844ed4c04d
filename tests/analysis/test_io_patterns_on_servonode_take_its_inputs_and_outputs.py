"""On ServoNode 51 a bit pattern past its six inputs or three outputs is error 3 in mint check as in mint-run.

INPUTMODE, INPUTACTIVELEVEL, INPUTPOSTRIGGER and INPUTNEGTRIGGER take a bitmap of the digital inputs
(000:12315-12316, 000:12293); their tables print no ServoNode 51 row, and every row they print is the pattern of all
the controller's inputs: NextMove PCI's 20 inputs 1048575, NextMove PC's 24 16777215, NextMove BX's 16 65535,
MintDrive's 18 262143 (000:11928-11931; 000:12281-12285, 12336-12340, 12400-12404, 12454-12458). ServoNode 51 has
6 (000:11932): 0 to 63, 2^6 - 1.

OUT sets the outputs as a bit pattern (000:14887-14893, 14922-14924: OUT = 266 makes outputs 1, 3 and 8 active).
Its table prints no ServoNode 51 row, and each row it prints is the pattern of all the controller's outputs:
NextMove PCI's and PC's 12, 0 ≤ x < 4096; NextMove BX's 8, 0 ≤ x < 256; MintDrive's 9, 0 ≤ x ≤ 511
(000:14906-14913, 4048). ServoNode 51 has 3 outputs (000:4048, 5618): 0 to 7, 2^3 - 1. The table's one range
holds for OUT.x too.

A value "outside of the accepted range of values" is #3 (000:18518-18521). Columns are the value's, counted by
hand from 1.
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
        pytest.param("OUT = 8\n", 7, id="OUT-one-past-the-third-output"),
        pytest.param("OUT = 266\n", 7, id="OUT-the-guides-example"),
        pytest.param("OUT = -1\n", 7, id="OUT-negative"),
    ],
)
def test_a_pattern_past_its_inputs_or_outputs_is_error_3_in_both_tools(source: str, column: int) -> None:
    assert _errors(source) == [("E0003", column)]
    result = simulate(source, controller="servonode51")
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 3, 1)


@pytest.mark.parametrize(
    "source",
    ["INPUTMODE = 63\n", "INPUTACTIVELEVEL = 0\n", "INPUTPOSTRIGGER = 0x20\n", "OUT = 7\n", "OUT = 0\n", "OUT.2 = 1\n"],
)
def test_a_pattern_of_its_inputs_or_outputs_passes_both_tools(source: str) -> None:
    assert _errors(source) == []
    assert simulate(source, controller="servonode51").stop.reason is StopReason.END
