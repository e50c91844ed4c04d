"""Where a run stops: the points of its timeline, and the plans that pick one forward or backward.

A *point* is one attempt of the interpreter to run a statement, numbered from
0 in the order they happen. The simulator is deterministic, so the number
names the same moment in every run of the same application with the same
interventions: stepping back to point ``k`` is running again, from a
checkpoint taken before ``k``, and stopping at ``k`` (``history.py``). A statement that blocks (``PAUSE``,
``WAIT``, a full move buffer) is attempted again on later ticks; those
attempts are *resumed* points, where stepping never stops, so ``next`` over a
``PAUSE`` stops after it has passed.

Forward plans stop at the first point they accept. Going back to a point the
run passed recently is one re-run that stops there (``reach``); further back,
a scan finds the last accepted point before the current one, and a second
re-run stops there. A re-run starts at a checkpoint (``checkpoints.py``): a
scan runs from the latest one before its end to its end, and from the one
before that if it found nothing, back to the start if need be.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from mintlang.records import record
from mintlang.runtime.interpreter.vm import Frame


@record
class Point:
    count: int  # attempts before this one, in this run
    pc: int  # the operation about to run
    depth: int  # GOSUB and event-handler frames open
    resumed: bool  # a blocked statement tried again (not a stop for stepping or breakpoints)
    tick: int = 0  # the simulated time, in servo ticks (ms)
    # The innermost GOSUB or handler open, None in the program's frame: a handler called again at the same depth
    # is another frame. Compared by identity, within one run.
    frame: Frame | None = field(default=None, compare=False, repr=False)


@record
class Forward:
    """Run on until ``accepts`` takes a point after ``after`` (or a breakpoint, or a pause request, stops it)."""

    after: int
    accepts: Callable[[Point], bool]
    reason: str = "step"
    breakpoints: bool = True  # whether breakpoints met on the way stop it
    wake: int | None = None  # a tick at which a blocked statement is tried again, so the plan can stop there


@dataclass(slots=True)
class Scan:
    """A re-run that stops nowhere: it finds the last point before ``until`` that ``wanted`` takes (given the
    point and whether a breakpoint hits there), among those from ``since``, where the re-run starts."""

    until: int
    wanted: Callable[[Point, bool], bool]
    reason: str
    found: int | None = field(default=None)
    since: int = 0
    pcs: frozenset[int] | None = None  # the only statements ``wanted`` can take, when it says

    def earlier(self) -> Scan:
        """The same search over the points before those this scan went through."""
        return Scan(self.since, self.wanted, self.reason, pcs=self.pcs)


def cont(after: int) -> Forward:
    return Forward(after, lambda point: False)


def entry() -> Forward:
    return Forward(-1, lambda point: point.count == 0, reason="entry")


def step_in(at: Point) -> Forward:
    return Forward(at.count, lambda point: not point.resumed)


def step_over(at: Point) -> Forward:
    """``next``: the next statement in this frame or a caller's; GOSUBs and event handlers run through, and so
    does a handler called again at this depth once this frame has returned (while the caller's PAUSE waits)."""

    def accepts(point: Point) -> bool:
        in_this_frame = point.depth == at.depth and point.frame is at.frame
        return not point.resumed and (point.depth < at.depth or in_this_frame)

    return Forward(at.count, accepts)


def step_out(at: Point) -> Forward:
    return Forward(at.count, lambda point: not point.resumed and point.depth < at.depth)


def run_for(at: Point, ticks: int) -> Forward:
    """On for ``ticks`` of simulated time, to the statement tried then (a blocked one is tried again at that
    tick, where the simulator would otherwise skip ahead), or the first after it if one runs through it."""
    until = at.tick + ticks
    return Forward(at.count, lambda point: point.tick >= until, wake=until)


def reach(count: int, reason: str) -> Forward:
    """The second pass of a backward plan: stop at point ``count`` and nowhere before."""
    return Forward(count - 1, lambda point: point.count == count, reason=reason, breakpoints=False)


def step_back(at: Point) -> Scan:
    """The reverse of ``next``: the statement before, in this frame or a caller's."""
    return Scan(at.count, lambda point, hit: not point.resumed and point.depth <= at.depth, "step")


def reverse_continue(at: Point, breakpoints: frozenset[int]) -> Scan:
    """Back to the last breakpoint hit before ``at``, at one of the statements ``breakpoints``; to the start when
    there is none."""
    return Scan(at.count, lambda point, hit: hit, "breakpoint", pcs=breakpoints)
