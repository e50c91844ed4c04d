"""Moves: what an axis (or a group of interpolated axes) is doing, as a function of time.

Every kind of motion implements ``Move``. A ``PlannedMove`` is a 1-D profile
along a path plus the geometry that turns the path position into each axis's
demand: a line for MOVE/VECTOR/JOG, an arc for CIRCLE. Axes that interpolate
share one move object, so they start, stop and finish together with the first
axis as master (spec MP-14, MP-15). Moves whose demand depends on more than
time (homing reacts to switches, following reads a master) say so with
``live`` and are updated on every profiler tick.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Protocol

from mintlang.runtime.clock import NEVER
from mintlang.runtime.motion.profile import Profile, plan_move, plan_velocity

PROFILER_TICK_MS = 2  # NextMove profiler period (T-1)


def next_profiler_tick(now: int) -> int:
    """The first profiler tick after ``now``: commands issued in a slice act there (T-6 RC)."""
    return now + PROFILER_TICK_MS - now % PROFILER_TICK_MS


def completion_tick(start: int, duration_s: float) -> int:
    """The first profiler tick whose profile time reaches the planned duration (T-6 RC 6)."""
    ticks = math.ceil(duration_s * 1000.0 / PROFILER_TICK_MS - 1e-9)
    return start + max(ticks, 0) * PROFILER_TICK_MS


class Move(Protocol):
    """The contract between an axis and whatever drives its demand."""

    mode: int  # the AXISMODE bit it shows
    axes: tuple[int, ...]  # the axes it moves, master first
    end: int  # the profiler tick at which it is complete; NEVER while open-ended
    buffered: bool  # it occupies a move-buffer slot while it runs
    live: bool  # its demand depends on more than time: every tick must be simulated

    def demand(self, index: int, tick: int) -> float:
        """The demand of its ``index``-th axis at ``tick`` (a profiler tick), in counts."""
        ...

    def velocity(self, index: int, tick: int) -> float:
        """The demand velocity of its ``index``-th axis, counts/s."""
        ...

    def profiler(self, tick: int) -> None:
        """A profiler tick is about to read the demand (a live move updates itself here)."""
        ...

    def stop(self, tick: int, decel: float) -> Move | None:
        """The move that replaces it on a controlled stop from ``tick``; None for a crash stop."""
        ...

    def replan(self, tick: int, speed: float, accel: float, decel: float, sramp: float) -> Move:
        """The same move after SPEED, ACCEL or DECEL changed (MP-10); itself when they do not apply."""
        ...


@dataclass(slots=True)
class Geometry:
    """Path position -> demand of each participating axis, in counts."""

    starts: tuple[float, ...]
    directions: tuple[float, ...]  # unit vector of a line; unused for arcs
    centre: tuple[float, float] | None = None
    radius: float = 0.0
    start_angle: float = 0.0  # radians
    turn: float = 1.0  # +1 anticlockwise, -1 clockwise

    def point(self, index: int, s: float) -> float:
        if self.centre is None:
            return self.starts[index] + self.directions[index] * s
        angle = self.start_angle + self.turn * s / self.radius
        return self.centre[index] + self.radius * (math.cos(angle) if index == 0 else math.sin(angle))

    def slope(self, index: int, s: float) -> float:
        """d(demand)/d(path) of one axis."""
        if self.centre is None:
            return self.directions[index]
        angle = self.start_angle + self.turn * s / self.radius
        return self.turn * (-math.sin(angle) if index == 0 else math.cos(angle))


@dataclass(slots=True)
class PlannedMove:
    """A profile along a path: positional moves, vectors, circles, jogs and the ramps that stop them."""

    mode: int
    axes: tuple[int, ...]
    geometry: Geometry
    profile: Profile
    start: int  # profiler tick the profile's time 0 falls on
    s_offset: float = 0.0  # path already covered before this profile (a re-plan continues the path)
    length: float | None = None  # the path length of a positional move; None for jogs and stops
    targets: tuple[float, ...] = ()  # end demands of a positional move (exact, free of rounding)
    buffered: bool = True
    live: bool = False
    feedrate: float | None = None  # the slew speed it keeps (FEEDRATEMODE), counts/s; None: the master's in force
    holds: PlannedMove | None = None  # the positional move this ramp holds at rest to resume (AX-18 mode 1, MT-16)
    jog: bool = False  # a JOG ramp, JOG = 0 included: rates written on the fly re-plan it (000:3103-3104)
    end: int = field(default=NEVER)

    def __post_init__(self) -> None:
        bounded = self.profile.final_velocity == 0.0
        self.end = completion_tick(self.start, self.profile.duration) if bounded else NEVER

    def path(self, tick: int) -> tuple[float, float]:
        """(path position, path velocity in counts/s) at ``tick``."""
        s, v = self.profile.sample(max(tick - self.start, 0) / 1000.0)
        return self.s_offset + s, v

    def demand(self, index: int, tick: int) -> float:
        if tick >= self.end and self.targets:
            return self.targets[index]
        return self.geometry.point(index, self.path(tick)[0])

    def velocity(self, index: int, tick: int) -> float:
        if tick >= self.end:
            return 0.0
        s, v = self.path(tick)
        return v * self.geometry.slope(index, s)

    def profiler(self, tick: int) -> None:
        return None

    def to_go(self, tick: int) -> float | None:
        """Path length left at ``tick`` of the positional move it is or holds (MP-11); None for a jog or a stop."""
        move = self if self.holds is None else self.holds
        if move.length is None:
            return None
        return max(move.length - self.path(tick)[0], 0.0)

    def goal(self, index: int, tick: int) -> float:
        """Where its ``index``-th axis ends the positional move it is or holds, in counts."""
        move = self if self.holds is None else self.holds
        return move.demand(index, move.end)

    def stop(self, tick: int, decel: float) -> PlannedMove:
        s, velocity = self.path(tick)
        ramp = plan_velocity(velocity, 0.0, decel, decel)
        return PlannedMove(self.mode, self.axes, self.geometry, ramp, tick, s, buffered=False)

    def replan(self, tick: int, speed: float, accel: float, decel: float, sramp: float) -> PlannedMove:
        if tick >= self.end:
            return self
        s, velocity = self.path(tick)
        if self.length is None:
            if not self.jog:
                return self  # a ramp of STOP, an error or a limit keeps the rate it began with
            ramp = plan_velocity(velocity, self.profile.final_velocity, accel, decel)
            return PlannedMove(self.mode, self.axes, self.geometry, ramp, tick, s, buffered=False, jog=True)
        slew = speed if self.feedrate is None else self.feedrate
        profile = plan_move(self.length - s, slew, accel, decel, velocity, sramp=sramp)
        return PlannedMove(
            self.mode, self.axes, self.geometry, profile, tick, s, self.length, self.targets, feedrate=self.feedrate
        )
