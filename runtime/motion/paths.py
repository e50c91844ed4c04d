"""Buffered path segments (MOVE, VECTOR, CIRCLE) and contouring: blending consecutive segments (MP-32..MP-34).

A ``PathSegment`` is what MOVEA/MOVER, VECTORA/VECTORR and CIRCLEA/CIRCLER put
in the move buffer. It knows its shape once it is placed at an origin (the
previous segment's exact end), so a running move can look ahead at the
segments waiting behind it. A segment loaded with contouring off becomes an
ordinary ``PlannedMove`` that stops at its end. One loaded with contouring on
starts a ``Chain``: a single profile over the whole length of the segments
that are loaded, triggered and joined to it, which takes the next ones out of
the buffer as the path reaches them and only brakes for the last one. The
chain is live because what it will do depends on moves the program has not
loaded yet.
"""

from __future__ import annotations

import math

from mintlang.records import record
from mintlang.runtime.motion.axis import MD_CIRCULAR, MD_LINEAR, Axis
from mintlang.runtime.motion.moves import Geometry, PlannedMove, completion_tick
from mintlang.runtime.motion.profile import Profile, plan_move, plan_velocity

CONTOUR_ON = 1  # _ctmCONTOUR_ON
VECTOR_ANGLE_ON = 2  # _ctmVECTOR_ANGLE_ON
PATH_MODES = frozenset({MD_LINEAR, MD_CIRCULAR})  # moves a MOVE, VECTOR or CIRCLE may be loaded behind (MP-13)


def exact_turn(degrees: float) -> tuple[float, float]:
    """(cos, sin) of an angle in degrees, exact on multiples of 90° so quarter and whole circles end exactly."""
    quarter, rest = divmod(degrees, 90.0)
    if rest == 0.0:
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[int(quarter) % 4]
    radians = math.radians(degrees)
    return math.cos(radians), math.sin(radians)


@record
class Arc:
    centre: tuple[float, float]  # counts, in the same frame as the demand
    degrees: float  # signed: positive anticlockwise; beyond ±360 it turns more than once


@record
class Shape:
    """A segment placed at its origin: where its path goes, how long it is, where it ends exactly."""

    geometry: Geometry
    length: float
    targets: tuple[float, ...]

    def tangent(self, s: float) -> tuple[float, ...]:
        return tuple(self.geometry.slope(index, s) for index in range(len(self.targets)))


@record
class PathSegment:
    """A buffered MOVE, VECTOR or CIRCLE; called with its start tick it becomes the move (``Request.build``)."""

    mode: int
    axes: tuple[Axis, ...]  # master first
    contour: int  # CONTOURMODE of the master when it was loaded: decides whether its end is a stop point
    targets: tuple[float, ...] = ()  # a line's end
    arc: Arc | None = None
    feedrate: float | None = None  # the slew speed it keeps (FEEDRATEMODE), counts/s; None: the master's when it runs

    def slew_speed(self) -> float:
        return self.axes[0].slew_speed() if self.feedrate is None else self.feedrate

    @property
    def numbers(self) -> tuple[int, ...]:
        return tuple(axis.number for axis in self.axes)

    def shape(self, origin: tuple[float, ...]) -> Shape:
        if self.arc is None:
            deltas = [target - start for target, start in zip(self.targets, origin, strict=True)]
            length = math.sqrt(sum(delta * delta for delta in deltas))
            directions = tuple(delta / length for delta in deltas) if length else tuple(0.0 for _ in deltas)
            return Shape(Geometry(origin, directions), length, self.targets)
        (cx, cy), degrees = self.arc.centre, self.arc.degrees
        dx, dy = origin[0] - cx, origin[1] - cy
        radius = math.hypot(dx, dy)
        cos, sin = exact_turn(degrees)
        end = (cx + dx * cos - dy * sin, cy + dx * sin + dy * cos)
        turn = 1.0 if degrees >= 0.0 else -1.0
        geometry = Geometry(origin, (0.0, 0.0), (cx, cy), radius, math.atan2(dy, dx), turn)
        return Shape(geometry, radius * math.radians(abs(degrees)), end)

    def __call__(self, tick: int) -> PlannedMove | Chain | None:
        shape = self.shape(tuple(axis.hold for axis in self.axes))
        if shape.length == 0.0:
            return None  # a move to where the axes already are generates no motion (MP-13)
        if self.contour & CONTOUR_ON:
            return Chain(self, shape, tick)
        p = self.axes[0].parameters
        profile = plan_move(shape.length, self.slew_speed(), p["ACCEL"], p["DECEL"], sramp=p["SRAMP"])
        return PlannedMove(
            self.mode,
            self.numbers,
            shape.geometry,
            profile,
            tick,
            0.0,
            shape.length,
            shape.targets,
            feedrate=self.feedrate,
        )


@record
class Plan:
    """A profile laid along a path from ``s_offset`` starting at profiler tick ``start``."""

    profile: Profile
    start: int
    s_offset: float

    def sample(self, tick: int) -> tuple[float, float]:
        s, v = self.profile.sample(max(tick - self.start, 0) / 1000.0)
        return self.s_offset + s, v

    @property
    def end(self) -> int:
        return completion_tick(self.start, self.profile.duration)


class Retimed:
    """A plan replaced from a profiler tick on; earlier ticks (interpolation, servo feed-forward) keep the old one."""

    __slots__ = ("earlier", "plan", "switch")

    def __init__(self, plan: Plan) -> None:
        self.earlier: Plan | None = None
        self.plan = plan
        self.switch = plan.start

    def replace(self, plan: Plan) -> None:
        self.earlier = self.plan if plan.start > self.plan.start else self.earlier
        self.plan = plan
        self.switch = plan.start

    def sample(self, tick: int) -> tuple[float, float]:
        if tick < self.switch and self.earlier is not None:
            return self.earlier.sample(tick)
        return self.plan.sample(tick)


@record
class Piece:
    segment: PathSegment
    shape: Shape
    s_start: float  # chain path position where it begins


class Chain:
    """Contoured segments traced at one path speed (MP-32, MP-34), braking only for the last one joined.

    Segment k blends into k+1 when k was loaded with contouring on, both move the
    same axes with the same master, k+1 is triggered by GO while the chain can
    still extend, and (with angle control) the corner between them is below
    CONTOURANGLE. The chain stops extending once it has begun its final
    deceleration: the axes then come to rest before anything else starts.
    """

    __slots__ = (
        "axes",
        "buffered",
        "current",
        "end",
        "extendable",
        "live",
        "members",
        "mode",
        "paused",
        "pieces",
        "timing",
    )

    def __init__(self, first: PathSegment, shape: Shape, tick: int) -> None:
        self.members = first.axes
        self.axes = first.numbers
        self.mode = first.mode
        self.pieces = [Piece(first, shape, 0.0)]
        self.current = 0
        self.buffered = True
        self.live = True
        self.extendable = True
        self.paused = False  # SUSPEND: at rest (or ramping to it) on the path, the segments ahead kept (MT-16)
        self.timing = Retimed(Plan(Profile(0.0, 0.0), tick, 0.0))
        self.end = tick
        self._plan(tick, 0.0, 0.0)
        self._extend(tick)

    @property
    def total(self) -> float:
        last = self.pieces[-1]
        return last.s_start + last.shape.length

    def _plan(self, tick: int, s: float, velocity: float) -> None:
        master = self.members[0]
        p = master.parameters
        speed = self._speed(master.slew_speed())
        self._lay(tick, s, velocity, speed=speed, accel=p["ACCEL"], decel=p["DECEL"], sramp=p["SRAMP"])

    def _speed(self, speed: float) -> float:
        """The path speed of the segment the path is on: its own feedrate, or ``speed`` where it keeps none."""
        feedrate = self.pieces[self.current].segment.feedrate
        return speed if feedrate is None else feedrate

    def _lay(
        self, tick: int, s: float, velocity: float, *, speed: float, accel: float, decel: float, sramp: float
    ) -> None:
        """Plan the rest of the path from ``s`` at ``velocity`` with these rates, from ``tick`` on."""
        profile = plan_move(self.total - s, speed, accel, decel, velocity, sramp=sramp)
        self.timing.replace(Plan(profile, tick, s))
        self.end = self.timing.plan.end

    def _rounding(self) -> float:
        """How far the float sums giving a path position may fall short of the exact one."""
        return 1e-9 * (1.0 + self.total)

    def _reached(self, s: float, start: float) -> bool:
        """Whether path position ``s`` has reached ``start``: 0.5 + 10 x 1.95 sums to just under 20, and the
        move starting at 20 must still be the running one on that tick (its MOVEBUFFERID, MOVEBUFFERLOW)."""
        return s >= start - self._rounding()

    def _feedrates_ahead(self) -> bool:
        """A joined segment still to come keeps a feedrate of its own: the path changes speed when it gets there."""
        return any(piece.segment.feedrate is not None for piece in self.pieces[self.current + 1 :])

    # ------------------------------------------------------------ Move protocol

    def _piece(self, s: float) -> Piece:
        """The piece under path position ``s``; past the end (a stop ramp) the last one continues its shape."""
        pieces, i = self.pieces, self.current
        while i > 0 and s < pieces[i].s_start:
            i -= 1
        while i + 1 < len(pieces) and s >= pieces[i + 1].s_start:
            i += 1
        return pieces[i]

    def demand(self, index: int, tick: int) -> float:
        if tick >= self.end and self.buffered and not self.paused:
            return self.pieces[-1].shape.targets[index]
        s, _ = self.timing.sample(tick)
        piece = self._piece(s)
        return piece.shape.geometry.point(index, s - piece.s_start)

    def velocity(self, index: int, tick: int) -> float:
        if tick >= self.end:
            return 0.0
        s, v = self.timing.sample(tick)
        piece = self._piece(s)
        return v * piece.shape.geometry.slope(index, s - piece.s_start)

    def to_go(self, tick: int) -> float:
        """Path length left at ``tick`` of the segment the path is on: the moves joined ahead of it are moves of
        their own in the buffer, not part of the one in progress (MP-11, MT-12)."""
        s, _ = self.timing.sample(tick)
        piece = self._piece(s)
        return max(piece.s_start + piece.shape.length - s, 0.0)

    def goal(self, index: int, tick: int) -> float:
        """Where its ``index``-th axis ends the segment the path is on at ``tick``, in counts."""
        return self._piece(self.timing.sample(tick)[0]).shape.targets[index]

    def profiler(self, tick: int) -> None:
        """Take the segments the path has reached out of the buffers, then look ahead for more; a segment that
        keeps another feedrate than the one before it changes the path speed from the tick it is reached (MT-15)."""
        s, v = self.timing.sample(tick)
        speed = self._speed(self.members[0].slew_speed())
        while self.current + 1 < len(self.pieces) and self._reached(s, self.pieces[self.current + 1].s_start):
            self.current += 1
            self.mode = self.pieces[self.current].segment.mode
            segment = self.pieces[self.current].segment
            for axis in self.members:  # an axis cancelled on its own has lost its buffer already
                if self.buffered and axis.buffer and axis.buffer[0].build is segment:
                    axis.started(axis.buffer.popleft())  # its MOVEBUFFERID is now the running one's (MT-12)
                    axis.triggered -= 1
        if self._speed(self.members[0].slew_speed()) != speed and tick < self.end and not self.paused:
            self._plan(tick, s, v)
        if self.paused and tick >= self.end:
            self.live = False  # at rest until resumed: no tick changes it
        self._extend(tick)

    def _extend(self, tick: int) -> None:
        if not self.extendable or self.paused:
            return
        s, v = self.timing.sample(tick)
        p = self.members[0].parameters
        braking_rate = p["DECEL"] * (1.0 - p["SRAMP"] / 200.0)
        remaining = self.total - s
        if v > 0.0 and remaining <= v * v / (2.0 * braking_rate) + self._rounding():
            self.extendable = False  # the final deceleration has begun (MP-34): no more joining
            self.live = self._feedrates_ahead()  # a speed still to change needs its tick
            return
        joined = False
        while (successor := self._joinable()) is not None:
            last = self.pieces[-1]
            self.pieces.append(Piece(successor, successor.shape(last.shape.targets), self.total))
            joined = True
        if joined:
            self._plan(tick, s, v)

    def _joinable(self) -> PathSegment | None:
        last = self.pieces[-1]
        if not last.segment.contour & CONTOUR_ON:
            return None
        waiting = len(self.pieces) - 1 - self.current  # joined segments still in the buffers
        for axis in self.members:
            if waiting >= axis.triggered or waiting >= len(axis.buffer):
                return None
        request = self.members[0].buffer[waiting]
        segment = request.build
        if not isinstance(segment, PathSegment) or segment.numbers != self.axes:
            return None
        if any(axis.buffer[waiting] is not request for axis in self.members):
            return None
        shape = segment.shape(last.shape.targets)
        if shape.length == 0.0:
            return None
        if last.segment.contour & VECTOR_ANGLE_ON:
            before, after = last.shape.tangent(last.shape.length), shape.tangent(0.0)
            cosine = max(-1.0, min(1.0, sum(a * b for a, b in zip(before, after, strict=True))))
            if math.degrees(math.acos(cosine)) >= self.members[0].contour_angle:
                return None  # CONTOURANGLE: this corner is a stop point (MP-33, ≥ per the v4 entry)
        return segment

    def stop(self, tick: int, decel: float) -> Chain:
        """Decelerate along the path; the joined segments still waiting are cleared with the buffer (MP-22)."""
        s, v = self.timing.sample(tick)
        self.timing.replace(Plan(plan_velocity(v, 0.0, decel, decel), tick, s))
        self.end = self.timing.plan.end
        self.extendable = False
        self.live = False
        self.buffered = False
        return self

    def pause(self, tick: int, decel: float) -> None:
        """SUSPEND: come to rest along the path at ``decel`` from ``tick`` and stay there (MT-16)."""
        s, v = self.timing.sample(tick)
        self.timing.replace(Plan(plan_velocity(v, 0.0, decel, decel), tick, s))
        self.end = self.timing.plan.end
        self.paused = True

    def resume(self, tick: int) -> None:
        """SUSPEND released: on along the path from where it is, as if the segments ahead were just joined."""
        self.paused = False
        self.live = self.extendable or self._feedrates_ahead()
        s, v = self.timing.sample(tick)
        self._plan(tick, s, v)

    def replan(self, tick: int, speed: float, accel: float, decel: float, sramp: float) -> Chain:
        """SPEED, ACCEL or DECEL changed: re-plan the rest of the path from where it is (MP-10, MP-36)."""
        if tick >= self.end or not self.buffered or self.paused:
            return self
        s, v = self.timing.sample(tick)
        self._lay(tick, s, v, speed=self._speed(speed), accel=accel, decel=decel, sramp=sramp)
        return self
