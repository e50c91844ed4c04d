"""A run taken back to a snapshot and run on from it goes exactly as the uninterrupted run went.

The debugger's checkpoints (``runtime/debugger/checkpoints.py``) rest on this:
a snapshot of the simulation (``runtime/snapshot.py``) taken before one tick,
restored after later ticks have changed everything, must make the following
ticks see the same state, tick for tick, and end as the run without it. Every
conformance case (motion, events, comms, cams, the v3 and MintMT machines) and
generated programs that wait, move, read keys and inputs and take timer events
are run both ways, with the state compared before each processed tick.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, note, settings
from hypothesis import strategies as st

from mintlang.runtime import snapshot
from mintlang.runtime.controller import Controller
from mintlang.runtime.observation import axis_state
from mintlang.runtime.run import RunResult, run_source
from mintlang.runtime.simulation import Limits, Rewind, Simulator
from tests.conformance.cases import CONFORMANCE, all_cases, read_case
from tests.runtime.programs import UNTIL_MS, Program, timed_programs
from tests.runtime.running import observable

UNBOUNDED_MS = 600_000


class Rewinder:
    """Records the state before each processed tick; saves it before tick ``save_at`` (or the first processed
    after it) and, at ``back_at``, takes the run back there once."""

    def __init__(self, save_at: int | None, back_at: int) -> None:
        self.save_at = save_at
        self.back_at = back_at
        self.states: list[tuple[object, ...]] = []
        self.saved: tuple[int, int, snapshot.Snapshot] | None = None  # (tick, states recorded before, snapshot)
        self.rewound = False
        self.simulator: Simulator | None = None

    def attach(self, simulator: Simulator) -> None:
        self.simulator = simulator
        simulator.before_tick = self.before_tick

    def before_tick(self, tick: int) -> None:
        assert self.simulator is not None
        if self.saved is None and self.save_at is not None and tick >= self.save_at:
            self.saved = (tick, len(self.states), snapshot.take([self.simulator], outside=[self]))
        elif self.saved is not None and not self.rewound and tick >= self.back_at:
            self.rewound = True
            saved_tick, recorded, taken = self.saved
            del self.states[recorded:]
            raise Rewind(saved_tick, taken.restore)
        self.states.append(state(self.simulator.c))


def state(controller: Controller) -> tuple[object, ...]:
    vm = controller.vm
    return (
        controller.clock.now,
        vm.pc,
        tuple(vm.scalars),
        tuple(map(tuple, vm.arrays)),
        tuple(frame.return_pc for frame in vm.frames),
        tuple(axis_state(axis) for axis in controller.axes),
        controller.io.active,
        controller.io.out,
        controller.terminal.text,
    )


def _both_ways(source: str, save_at: int, back_at: int, **run: object) -> tuple[RunResult, RunResult, Rewinder]:
    plain = Rewinder(save_at=None, back_at=0)  # records, never goes back
    uninterrupted = run_source(source, on_simulator=plain.attach, **run)  # type: ignore[arg-type]
    rewinder = Rewinder(save_at, back_at)
    rewound = run_source(source, on_simulator=rewinder.attach, **run)  # type: ignore[arg-type]
    assert rewinder.states == plain.states
    return uninterrupted, rewound, rewinder


CASES = all_cases()


@pytest.mark.parametrize("path", CASES, ids=[str(path.relative_to(CONFORMANCE)) for path in CASES])
def test_a_conformance_case_taken_back_halfway_ends_as_it_does_uninterrupted(path: Path) -> None:
    case = read_case(path)
    until = case.until_ms or UNBOUNDED_MS
    run = {
        "config": case.configuration,
        "controller": case.controller,
        "dialect": case.dialect,
        "scenario": case.scenario,
        "limits": Limits(until_ms=until, max_wall_s=60.0),
    }
    first = run_source(case.source, **run)  # type: ignore[arg-type]
    end = first.stop.time_ms
    uninterrupted, rewound, _ = _both_ways(case.source, end // 3, 2 * end // 3 + 1, **run)
    assert observable(rewound) == observable(uninterrupted)
    assert rewound.outcomes == uninterrupted.outcomes


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(program=timed_programs(), save_at=st.integers(0, UNTIL_MS), span=st.integers(1, UNTIL_MS))
def test_a_generated_program_taken_back_runs_on_as_it_ran(program: Program, save_at: int, span: int) -> None:
    note(program.source)
    limits = Limits(until_ms=UNTIL_MS, max_wall_s=None)
    uninterrupted, rewound, _ = _both_ways(program.source, save_at, save_at + span, limits=limits)
    assert observable(rewound) == observable(uninterrupted)


def test_restoring_puts_back_lists_dictionaries_attributes_and_closure_cells_in_the_same_objects() -> None:
    class Box:  # a class of the tests: the walk takes only the runtime's own classes, so it is named outside
        pass

    values = [1.0, 2.0]
    table = {"a": values}

    def counter() -> object:
        count = 0

        def bump() -> int:
            nonlocal count
            count += 1
            return count

        return bump

    bump = counter()
    bump()
    taken = snapshot.take([table, bump])
    values.append(3.0)
    table["b"] = []
    bump()
    taken.restore()
    assert table == {"a": [1.0, 2.0]} and table["a"] is values
    assert bump() == 2  # the cell held 1 when saved
    with pytest.raises(snapshot.NotSnapshotted, match="Box"):
        snapshot.take([[Box()]])
