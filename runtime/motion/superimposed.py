"""An OFFSET superimposed on a FOLLOW move: a relative move on top of the master's speed (spec MP-18).

The axis runs the OFFSET's own SPEED, ACCEL and DECEL profile relative to its
base velocity, whatever the master does (000:14774-14784, 3503-3512); AXISMODE
shows FOLLOW and OFFSET together while it runs (000:7119-7120). A STOP cancels
it at once, keeping the distance already covered (000:14806-14808).
"""

from __future__ import annotations

from dataclasses import field

from mintlang.records import record
from mintlang.runtime.motion.moves import completion_tick
from mintlang.runtime.motion.profile import Profile


@record
class Offset:
    """One OFFSET's profile, started at profiler tick ``start``; ``sign`` gives its direction."""

    profile: Profile
    start: int
    sign: float

    @property
    def end(self) -> int:
        return completion_tick(self.start, self.profile.duration)

    def covered(self, tick: int) -> float:
        """Counts added by ``tick``."""
        return self.sign * self.profile.sample(max(tick - self.start, 0) / 1000.0)[0]


@record(frozen=False)
class OffsetTrack:
    """What the OFFSETs of one following move have added to its demand: those finished and the one running."""

    finished: float = 0.0
    running: Offset | None = None
    last: float = field(default=0.0)  # the total at the last profiler tick, for moves that add increments

    def total(self, tick: int) -> float:
        """The counts added at ``tick``; an offset that is over joins the finished ones."""
        running = self.running
        if running is None:
            return self.finished
        if tick >= running.end:
            self.finished += running.covered(running.end)
            self.running = None
            return self.finished
        return self.finished + running.covered(tick)

    def increment(self, tick: int) -> float:
        """The counts added since the last profiler tick."""
        total = self.total(tick)
        step, self.last = total - self.last, total
        return step

    def cancel(self, tick: int) -> None:
        """STOP: the offset ends where it is."""
        self.finished = self.total(tick)
        self.running = None
