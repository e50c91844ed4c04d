"""Checkpoints of the run under the debugger: the states going back restores, to run on from them.

Going back to point ``k`` restores the latest checkpoint taken before ``k`` and
runs on from it to ``k`` (``execution.py``): the simulator is deterministic,
so the state there is the state the run had. A checkpoint is taken before a
processed tick, once the run has done another ``INTERVAL`` of *work* (points
tried, plus ``TICK_WORK`` for each tick processed: what a re-run costs), so
going back to the recent past re-runs at most that much. The interval weighs
the time to re-run it against the time to save a checkpoint, a tenth of it.

Older checkpoints are thinned out as the run goes on: the ``2 * DENSE`` most
recent are kept, then every second one of the next ``2 * DENSE`` intervals,
every fourth of the next ``4 * DENSE`` and so on (a checkpoint's number on the
grid of intervals decides, so one dropped is never wanted again). Going back
costs about as much as the distance back, and the number kept grows with the
logarithm of the run's length, to ``LIMIT`` at most: beyond it the oldest go,
never the first, taken before the first tick, from which any point is reached.

Each checkpoint also keeps the statements tried in its *stretch*, up to the
next one kept (a thinned one's stretch joins the one before): a search for the
last hit of a breakpoint skips the stretches that never passed one.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import field

from mintlang.records import record
from mintlang.runtime.snapshot import Snapshot

INTERVAL = 4096  # work between two checkpoints: some 30 ms to re-run, against 3-5 ms to save one
TICK_WORK = 5  # the work of a processed tick, in statements tried: the servo loop of every axis, the I/O, the events
DENSE = 4  # checkpoints kept at each spacing, from one interval apart to far apart
LIMIT = 48  # checkpoints kept at most: each holds the simulation's state (about 100 kB for 12 axes)


@record
class Checkpoint:
    """The run as it stood before processing ``tick``: the simulation and the debugger's account of the run."""

    serial: int  # its place on the grid of intervals: the work done before it, in intervals
    tick: int
    count: int  # points tried before it: the first point a run from it reaches
    ticks: int  # ticks processed before it
    writes: int  # the program's writes to the terminal before it
    blocked: tuple[int | None, ...]  # by frame depth: the statement waiting there, if one is
    hits: Mapping[tuple[object, ...], int]  # each breakpoint's hit count, by what makes it the same breakpoint
    state: Snapshot
    passed: set[int] = field(default_factory=set)  # the statements (pcs) tried in its stretch, not as retries


def _kept(serial: int, newest: int) -> bool:
    """Whether the checkpoint numbered ``serial`` is kept once ``newest`` has been taken: those ``age`` intervals
    back are kept one in ``2 ** level``, where the level grows by one each time the age doubles."""
    level = max(0, (max(newest - serial, 0) // DENSE).bit_length() - 1)
    return serial % (1 << level) == 0


class Checkpoints:
    """The checkpoints of one run, in the order of the run."""

    def __init__(self) -> None:
        self.kept: list[Checkpoint] = []
        self.newest = -1  # the highest serial taken

    def __len__(self) -> int:
        return len(self.kept)

    def numbered(self, serial: int) -> Checkpoint | None:
        return next((checkpoint for checkpoint in reversed(self.kept) if checkpoint.serial == serial), None)

    def wanted(self, serial: int) -> bool:
        """Whether a checkpoint numbered ``serial`` is to be taken now (not taken yet, not thinned out)."""
        return self.numbered(serial) is None and _kept(serial, max(self.newest, serial))

    def add(self, checkpoint: Checkpoint) -> None:
        """Keep ``checkpoint``, and thin out the older ones: a stretch dropped joins the one before it."""
        ordered = sorted([*self.kept, checkpoint], key=lambda kept: kept.serial)
        self.newest = max(self.newest, checkpoint.serial)
        survivors: list[Checkpoint] = []
        for kept in ordered:
            if survivors and not _kept(kept.serial, self.newest):
                survivors[-1].passed.update(kept.passed)
            else:
                survivors.append(kept)
        for dropped in survivors[1 : max(1, len(survivors) - LIMIT + 1)]:
            survivors[0].passed.update(dropped.passed)
        del survivors[1 : max(1, len(survivors) - LIMIT + 1)]
        self.kept = survivors

    def latest(self, count: int) -> Checkpoint | None:
        """The latest checkpoint a run from which reaches point ``count``."""
        return next((checkpoint for checkpoint in reversed(self.kept) if checkpoint.count <= count), None)

    def search_from(self, until: int, pcs: frozenset[int] | None) -> tuple[Checkpoint, int] | None:
        """Where a search for the last point before ``until`` at one of the statements ``pcs`` (any, if None)
        starts, and where it can end: the latest checkpoint before ``until`` whose stretch passed one, and the
        end of that stretch. None when no stretch did."""
        end = until
        for checkpoint in reversed(self.kept):
            if checkpoint.count >= until:
                continue
            if pcs is None or not checkpoint.passed.isdisjoint(pcs):
                return checkpoint, end
            end = checkpoint.count
        return None

    def forget_after(self, count: int) -> None:
        """What happened at point ``count`` changed (a value set there, or undone): later checkpoints no longer hold."""
        self.kept = [checkpoint for checkpoint in self.kept if checkpoint.count <= count]
        self.newest = self.kept[-1].serial if self.kept else -1
