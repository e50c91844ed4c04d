"""Monitors: parts of a dialect's machine that act on the motion of each processed tick.

A monitor is told before and after the motion step of a tick (moves ending,
the next ones starting), so it can see what the motion changed and nothing
else (the program's statements run after it), and it says which tick it next
needs processed, so skipping idle ticks never makes it late.
"""

from __future__ import annotations

from typing import Protocol


class Monitor(Protocol):
    def before_motion(self, tick: int) -> None:
        """The tick's motion is about to run."""
        ...

    def after_motion(self, tick: int) -> None:
        """The tick's motion has run: moves that ended have left their buffers, the next ones have started."""
        ...

    def next_required(self, now: int) -> int:
        """The next tick this monitor must see (``NEVER`` when none)."""
        ...
