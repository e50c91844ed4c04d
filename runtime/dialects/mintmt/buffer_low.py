"""MOVEBUFFERLOW: the event that asks the program to restock an axis's move buffer (004:109-134, MT-14).

``MOVEBUFFERLOW(axis) = n`` sets the level: when a move leaves that axis's
buffer and the number of free places rises to ``n`` (from below it), the
``Event MOVEBUFFERLOW`` block is called. Only the motion frees places this way:
a program that empties the buffer (STOP) or makes it larger does not raise the
event, and neither does an axis already that low when the level is written.
The level 0, at power-up, is never reached from below: no event.
"""

from __future__ import annotations

from mintlang.runtime.clock import NEVER
from mintlang.runtime.events import EventClass, Events
from mintlang.runtime.keywords import KeywordTable, per_channel
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.ranges import ranged


class BufferLowEvent:
    """The level of each axis, and the free places it had before each tick's motion (a ``Monitor``)."""

    def __init__(self, motion: Motion, events: Events) -> None:
        self.motion = motion
        self.events = events
        self.levels: dict[int, int] = {}  # axis -> level, for the axes whose level is above 0
        self._free_before: dict[int, int] = {}

    def register(self, table: KeywordTable) -> None:
        # MT-14: whole, 0 or more
        write = ranged("MOVEBUFFERLOW", table.controller, self._write, table.dialect, channel=self.motion.axis_number)
        table.register("MOVEBUFFERLOW", read=self._read, write=per_channel(write))

    def _read(self, channel: int | None) -> float:
        return float(self.levels.get(self.motion.axis(channel).number, 0))

    def _write(self, channel: int | None, value: float) -> None:
        axis = self.motion.axis(channel)
        if value:
            self.levels[axis.number] = int(value)
        else:
            self.levels.pop(axis.number, None)

    def before_motion(self, tick: int) -> None:
        axes = self.motion.axes
        self._free_before = {number: axes[number].buffer_free() for number in self.levels}

    def after_motion(self, tick: int) -> None:
        axes = self.motion.axes
        for number, level in self.levels.items():
            before = self._free_before.get(number, level)
            if before < level <= axes[number].buffer_free() and self.events.has_handler(EventClass.MOVEBUFFERLOW):
                self.events.raise_event(EventClass.MOVEBUFFERLOW)

    def next_required(self, now: int) -> int:
        """The tick a move of a watched axis ends, when a place frees; a live move frees them on any tick, a held
        one (SUSPEND, a stop input) on none."""
        soonest = NEVER
        for number in self.levels:
            axis = self.motion.axes[number]
            move = axis.move
            if move is not None and not axis.held:
                soonest = min(soonest, now + 1 if move.live else max(move.end, now + 1))
        return soonest
