"""Output moves take no time (mintlang/MINTMT.md, MT-22).

However many output moves stand between the moves of a buffer, the axis ends
where and when it would without them, and each output move has set its channel.
"""

from __future__ import annotations

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from mintlang.runtime.run import run_source
from mintlang.runtime.simulation import Limits
from tests.fuzzing import examples

HEADER = "SPEED(0) = 5000 : ACCEL(0) = 50000 : DECEL(0) = 50000\nMOVEBUFFERSIZE(0) = 20\n"
FOOTER = "GO(0)\nPause IDLE(0)\nPrint TIME\n"

distances = st.lists(st.integers(min_value=-5000, max_value=5000).filter(bool), min_size=1, max_size=4)
channels = st.lists(st.sets(st.integers(min_value=0, max_value=7), max_size=2), min_size=4, max_size=4)


def _run(moves: list[int], outputs: list[set[int]]) -> tuple[float, float, int]:
    lines = [HEADER]
    for distance, after in zip(moves, outputs, strict=False):
        lines.append(f"MOVER(0) = {distance}\n")
        lines.extend(f"MOVEOUTX(0,{channel}) = 1\n" for channel in sorted(after))
    lines.append(FOOTER)
    result = run_source("".join(lines), dialect="mintmt", config="RESETALL\n", limits=Limits(until_ms=60_000))
    return result.axes[0].pos, float(result.terminal), result.outputs


@settings(max_examples=examples(12), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(moves=distances, outputs=channels)
def test_output_moves_change_neither_where_nor_when_the_motion_ends(moves: list[int], outputs: list[set[int]]) -> None:
    with_outputs = _run(moves, outputs)
    without = _run(moves, [set() for _ in outputs])
    expected_outputs = sum(1 << channel for channel in set().union(*outputs[: len(moves)]))
    assert with_outputs == (without[0], without[1], expected_outputs)
    assert without[0] == sum(moves)
