"""``Limits.settle`` runs the machine on after END until every axis is idle, and ``on_start`` hands over the
controller before the first tick: what ``mint-migrate --verify`` needs to compare two runs whose programs
end at different times (runtime/BEHAVIOUR.md, "Running on after END")."""

from __future__ import annotations

from mintlang.runtime.controller import Controller
from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import run_source
from mintlang.runtime.simulation import Limits

# 1000 counts at the v4 defaults (SPEED 20000, ACCEL = DECEL 300000): a triangle of peak
# sqrt(1000 * 300000) = 17320.5 counts/s lasting 2 * 17320.5 / 300000 s = 115.5 ms, started
# by the profiler at 2 ms and complete at the first profiler tick past 117.5 ms: 118 ms.
PROGRAM = "REM @sim drives enabled\nMOVEA.0 = 1000 : GO.0\n"


def _run(settle: bool) -> tuple[StopReason, int, list[int], float]:
    ticks: list[int] = []
    result = run_source(
        PROGRAM, limits=Limits(until_ms=1000, every_tick=True, settle=settle), on_tick=lambda _, t: ticks.append(t)
    )
    return result.stop.reason, result.stop.time_ms, ticks, result.axes[0].pos


def test_without_settle_the_run_stops_at_end_with_the_move_under_way() -> None:
    reason, ended, ticks, pos = _run(settle=False)
    assert (reason, ended, ticks, pos) == (StopReason.END, 0, [0], 0.0)


def test_with_settle_the_move_finishes_and_the_stop_is_still_the_end() -> None:
    reason, ended, ticks, pos = _run(settle=True)
    assert (reason, ended, pos) == (StopReason.END, 0, 1000.0)
    assert ticks == list(range(ticks[-1] + 1))
    assert ticks[-1] == 118  # idle on the tick the move completes: the axis rests on the target


def test_settle_stops_at_the_time_limit() -> None:
    ticks: list[int] = []
    result = run_source(
        "REM @sim drives enabled\nJOG.0 = 100\n",
        limits=Limits(until_ms=50, every_tick=True, settle=True),
        on_tick=lambda _, t: ticks.append(t),
    )
    assert result.stop.reason is StopReason.END
    assert ticks[-1] == 50


def test_on_start_sees_the_controller_before_the_first_tick() -> None:
    seen: list[tuple[str, int]] = []
    holder: list[Controller] = []

    def echo(text: str) -> None:
        site = holder[0].vm.current_site()
        seen.append((text, site.line if site else -1))

    run_source('PRINT "a"\nWAIT = 3\nPRINT "b"\n', echo=echo, on_start=holder.append)
    assert [(text, line) for text, line in seen] == [("a\n", 1), ("b\n", 3)]  # each PRINT is one write
