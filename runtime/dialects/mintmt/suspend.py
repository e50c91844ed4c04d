"""SUSPEND: a temporary stop of the motion in the move buffer (004:248, 000:17775; MT-16).

``SUSPEND(axis) = 1`` brings the move the axis runs from its buffer to rest
along its path at the master's DECEL and keeps it there, with every move
waiting behind it; no move of the buffer starts while it lasts. ``SUSPEND = 0``
lets the move finish from where it stopped, ramping up at ACCEL, and the
buffer go on. A move of several axes waits until none of them is suspended.
The note's single stepping is given no value, so any value but 0 and 1 is not
simulated; nor is a move that does not come from the buffer (JOG, HOME ...).
"""

from __future__ import annotations

from collections.abc import Callable

from mintlang.records import record
from mintlang.runtime.errors import NotSimulated
from mintlang.runtime.keywords import KeywordTable, per_channel
from mintlang.runtime.motion.axis import Axis
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.motion.holding import hold, release
from mintlang.runtime.motion.moves import Move, PlannedMove, next_profiler_tick
from mintlang.runtime.motion.paths import Chain
from mintlang.runtime.ranges import ranged

RUNNING, SUSPENDED = 0, 1


@record
class _Paused:
    axes: tuple[int, ...]  # the axes of the paused move
    moving: Move  # what they run while it is paused (a Chain, or the held move's ramp)
    resume: Callable[[], None]


class Suspension:
    """Which axes are suspended, and the moves paused for them until none of their axes is."""

    def __init__(self, motion: Motion) -> None:
        self.motion = motion
        self.suspended: set[int] = set()
        self.paused: list[_Paused] = []

    def register(self, table: KeywordTable) -> None:
        # MT-16: whole, 0 or more
        write = ranged("SUSPEND", table.controller, self._write, table.dialect, channel=self.motion.axis_number)
        table.register("SUSPEND", read=self._read, write=per_channel(write))

    def _read(self, channel: int | None) -> float:
        return float(SUSPENDED if self.motion.axis(channel).number in self.suspended else RUNNING)

    def _write(self, channel: int | None, value: float) -> None:
        axis = self.motion.axis(channel)
        if value not in (RUNNING, SUSPENDED):
            raise NotSimulated("SUSPEND", f"the value {value:g}: single stepping, whose values the notes do not give")
        if value == SUSPENDED:
            self._suspend(axis)
        else:
            self._resume(axis)

    def _suspend(self, axis: Axis) -> None:
        if axis.number in self.suspended:
            return
        move = axis.move
        if move is not None and not any(paused.moving is move for paused in self.paused):
            self.paused.append(self._pause(axis, move))
        self.suspended.add(axis.number)
        axis.held = True  # nothing in its buffer starts while it is suspended

    def _pause(self, axis: Axis, move: Move) -> _Paused:
        motion = self.motion
        tick = next_profiler_tick(motion.clock.now)
        decel = motion.path_master(axis).parameters["DECEL"]
        if isinstance(move, Chain):
            move.pause(tick, decel)
            for member in move.members:
                member.held = True
            return _Paused(move.axes, move, lambda: move.resume(next_profiler_tick(motion.clock.now)))
        if type(move) is PlannedMove and move.buffered and move.length is not None:
            held = hold(motion, move, tick, decel)
            return _Paused(move.axes, held.ramp, lambda: release(motion, held))
        raise NotSimulated("SUSPEND", "of a move that does not come from the move buffer")

    def _resume(self, axis: Axis) -> None:
        self.suspended.discard(axis.number)
        if axis.move is None:
            axis.held = False
        for paused in [paused for paused in self.paused if not self.suspended.intersection(paused.axes)]:
            self.paused.remove(paused)
            axes = [self.motion.axes[number] for number in paused.axes]
            for member in axes:
                member.held = False
            if any(member.move is paused.moving for member in axes):  # not stopped or taken over meanwhile
                paused.resume()
