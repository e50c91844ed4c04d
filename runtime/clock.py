"""Simulated time and how long what the program just read stays true.

Time advances in servo ticks of 1 ms. A blocked program (``PAUSE``, ``WAIT``,
a full move buffer) is woken only when something it depends on can change, so
readers of time-varying values lower ``horizon`` to the first tick at which
their value may differ. The simulation then jumps straight to the next tick at
which anything can happen; this is what lets a program that mostly waits run
thousands of times faster than real time with the same results tick for tick.
"""

from __future__ import annotations

NEVER = 1 << 62  # a tick that never comes


class Clock:
    __slots__ = ("horizon", "now")

    def __init__(self) -> None:
        self.now = 0  # the current servo tick, in ms since RUN
        self.horizon = NEVER  # the earliest tick at which something read since the last reset may change

    def changes_at(self, tick: int) -> None:
        """A value just read may change at ``tick``."""
        self.horizon = min(self.horizon, tick)

    def changes_next_tick(self) -> None:
        self.changes_at(self.now + 1)
