"""INCA / INCR: a positional move whose end point may be changed while it runs (spec MP-17).

The first INCA/INCR needs an axis with nothing to do and GO, like MOVEA.
Until it starts, further loads only move its end point; once it runs, each
INCA/INCR re-plans it from the next profiler tick with the current position
and velocity, so the axis speeds up, slows down or turns round (``plan_move``)
and comes to rest on the newest target. INCR is relative to the target, not
to the position [000:3158-3166].
"""

from __future__ import annotations

from collections.abc import Callable

from mintlang.runtime.errors import MintError
from mintlang.runtime.keywords import Channels, KeywordTable, Values
from mintlang.runtime.motion.axis import MD_INCREMENT, MOTION_IN_PROGRESS, Axis, Request
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.motion.moves import Geometry, PlannedMove, next_profiler_tick
from mintlang.runtime.motion.paths import Plan, Retimed
from mintlang.runtime.motion.profile import plan_move, plan_velocity


class IncrementalMove:
    """One axis travelling to a target that INCA/INCR may move; re-plans take effect at a profiler tick."""

    __slots__ = ("axis", "end", "origin", "target", "timing")

    mode = MD_INCREMENT
    buffered = True
    live = False

    def __init__(self, axis: Axis, origin: float, target: float, tick: int) -> None:
        self.axis = axis
        self.origin = origin
        self.target = target
        self.timing = Retimed(self._plan(tick, 0.0, 0.0))
        self.end = self.timing.plan.end

    @property
    def axes(self) -> tuple[int, ...]:
        return (self.axis.number,)

    def _plan(self, tick: int, s: float, velocity: float) -> Plan:
        p = self.axis.parameters
        distance = self.target - self.origin - s
        speed = self.axis.slew_speed()
        return Plan(plan_move(distance, speed, p["ACCEL"], p["DECEL"], velocity, sramp=p["SRAMP"]), tick, s)

    def retarget(self, target: float, tick: int) -> None:
        """A new end point from ``tick`` on, reached from the present position and velocity."""
        self.target = target
        s, velocity = self.timing.sample(tick)
        self.timing.replace(self._plan(tick, s, velocity))
        self.end = self.timing.plan.end

    def demand(self, index: int, tick: int) -> float:
        if tick >= self.end:
            return self.target
        return self.origin + self.timing.sample(tick)[0]

    def velocity(self, index: int, tick: int) -> float:
        return 0.0 if tick >= self.end else self.timing.sample(tick)[1]

    def profiler(self, tick: int) -> None:
        return None

    def stop(self, tick: int, decel: float) -> PlannedMove:
        s, velocity = self.timing.sample(tick)
        ramp = plan_velocity(velocity, 0.0, decel, decel)
        return PlannedMove(self.mode, self.axes, Geometry((self.origin,), (1.0,)), ramp, tick, s, buffered=False)

    def replan(self, tick: int, speed: float, accel: float, decel: float, sramp: float) -> IncrementalMove:
        if tick < self.end:
            s, velocity = self.timing.sample(tick)
            profile = plan_move(self.target - self.origin - s, speed, accel, decel, velocity, sramp=sramp)
            self.timing.replace(Plan(profile, tick, s))
            self.end = self.timing.plan.end
        return self


def incremental(motion: Motion, *, relative: bool) -> Callable[[Channels | None, Values], bool]:
    """The writer of INCA (absolute end point) or INCR (end point moved by the value)."""

    def write(channels: Channels | None, values: Values) -> bool:
        pairs = motion._pairs(channels, values)
        motion.check_values("INCR" if relative else "INCA", pairs)
        for axis, _ in pairs:
            axis.require_ready()
            if not (_running(axis) or _waiting(axis) or not axis.busy()):
                raise MintError(MOTION_IN_PROGRESS, axis.number, "INCA/INCR needs an idle axis or an incremental move")
        tick = next_profiler_tick(motion.clock.now)
        for axis, value in pairs:
            if relative:
                base = axis.target if _running(axis) or _waiting(axis) else axis.reference()
                target = base + value * axis.scale
            else:
                target = axis.absolute(value * axis.scale)
            running = _running(axis)
            if running is not None:
                running.retarget(target, tick)
            elif not _waiting(axis):
                axis.buffer.append(Request(MD_INCREMENT, (axis.number,), _starter(axis), ident=axis.load_ident))
            axis.target = target
        return False

    return write


def _running(axis: Axis) -> IncrementalMove | None:
    move = axis.move
    return move if isinstance(move, IncrementalMove) and not axis.buffer else None


def _waiting(axis: Axis) -> bool:
    """An incremental move loaded and not started yet: a new end point simply replaces its target."""
    return len(axis.buffer) == 1 and axis.buffer[0].mode == MD_INCREMENT and axis.move is None


def _starter(axis: Axis) -> Callable[[int], IncrementalMove | None]:
    def build(tick: int) -> IncrementalMove | None:
        if axis.target == axis.hold:
            return None  # already at the end point: no move (MP-17)
        return IncrementalMove(axis, axis.hold, axis.target, tick)

    return build


def register(table: KeywordTable, motion: Motion) -> None:
    table.register("INCA", write=incremental(motion, relative=False))
    table.register("INCR", write=incremental(motion, relative=True))
