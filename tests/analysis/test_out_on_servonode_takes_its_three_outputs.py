"""On ServoNode 51, OUT written past its three outputs is error 3 in mint check as in mint-run.

OUT sets the outputs as a bit pattern (000:14887-14893, 14922-14924: OUT = 266 makes outputs 1, 3 and 8
active). Its table prints no ServoNode 51 row, and each row it prints is the pattern of all the controller's
outputs: NextMove PCI's and PC's 12, 0 ≤ x < 4096; NextMove BX's 8, 0 ≤ x < 256; MintDrive's 9, 0 ≤ x ≤ 511
(000:14906-14913, 4048). ServoNode 51 has 3 outputs (000:4048, 5618): 0 to 7, 2^3 - 1; a value "outside of
the accepted range of values" is #3 (000:18518-18521). The table's one range holds for OUT.x too.
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
        pytest.param("OUT = 8\n", 7, id="one-past-the-third-output"),
        pytest.param("OUT = 266\n", 7, id="the-guides-example"),
        pytest.param("OUT = -1\n", 7, id="negative"),
    ],
)
def test_a_pattern_past_the_third_output_is_error_3_in_both_tools(source: str, column: int) -> None:
    assert _errors(source) == [("E0003", column)]
    result = simulate(source, controller="servonode51")
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 3, 1)


@pytest.mark.parametrize("source", ["OUT = 7\n", "OUT = 0\n", "OUT.2 = 1\n"])
def test_a_pattern_of_its_three_outputs_passes_both_tools(source: str) -> None:
    assert _errors(source) == []
    assert simulate(source, controller="servonode51").stop.reason is StopReason.END
