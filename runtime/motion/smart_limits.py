"""SOFTLIMITMODE 4, the smart mode of NextMove: a software limit becomes the end point of the move.

A move that would carry an axis past one of its software limits, in the direction it
travels, is ramped down at ``DECEL`` so that it comes to rest on the limit, and is held
there as a stop input holds a move (``holding.py``): it does not complete and ``IDLE``
stays 0. At rest the limit's bit is latched in ``AXISERROR`` and ``#ONERROR`` becomes
pending; nothing more is done: the handler is not called again for that bit while the move
waits on the limit, as it is for other latched errors (AX-7). Writing that limit further out (or leaving mode 4) lets
the move go on, to its end or to the new limit; ``STOP`` and ``CANCEL`` end it
(000:16057-16068). The guide names the moves this applies to (000:16073-16074): MOVEA,
MOVER, VECTORA, VECTORR, CIRCLEA, CIRCLER and JOG, here with the ramp a ``STOP`` gives
them. Any other motion that passes a limit in mode 4 is crash-stopped, as mode 3 does
where it cannot ramp (000:16091-16093); the guide does not say.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from mintlang.records import record
from mintlang.runtime.motion.axis import ER_FWD_SOFT, ER_REV_SOFT, MD_CIRCULAR, MD_JOG, MD_LINEAR, Axis
from mintlang.runtime.motion.commands import SMART_SOFT_LIMITS, Motion
from mintlang.runtime.motion.holding import Held, hold_on, release
from mintlang.runtime.motion.moves import PROFILER_TICK_MS, Geometry, PlannedMove
from mintlang.runtime.motion.profile import plan_move

_SMART_MOVES = frozenset({MD_LINEAR, MD_CIRCULAR, MD_JOG})
_LIMITS = {ER_FWD_SOFT: "SOFTLIMITFORWARD", ER_REV_SOFT: "SOFTLIMITREVERSE"}  # AXISERROR bit -> its limit
_LIMIT_PARAMETERS = (*_LIMITS.values(), "SOFTLIMITMODE")


@record(frozen=False)
class _Stop:
    """A move held on the software limit of one of its axes."""

    held: Held
    axis: int  # the axis whose limit it stops on
    bit: int  # that limit's AXISERROR bit
    limit: float  # the limit, in counts, as it was written
    reported: bool = False  # #ONERROR made pending at rest


@record
class _Crossing:
    path: float  # the path position at which the axis reaches the limit (or is already past it)
    axis: int
    bit: int
    limit: float


class SmartLimits:
    """Anticipates the software limits of the axes in mode 4, once per profiler tick of each move."""

    def __init__(self, motion: Motion, raise_error: Callable[[Axis], None]) -> None:
        self.motion = motion
        self.raise_error = raise_error
        self.stops: list[_Stop] = []
        self._cleared: dict[int, tuple[PlannedMove, tuple[float, ...]]] = {}  # axis -> move and limits found clear

    def check(self, axis: Axis, tick: int) -> bool:
        """Whether the software-limit bits of ``axis`` are this module's, not the error modes', this tick."""
        if int(axis.parameters["SOFTLIMITMODE"]) != SMART_SOFT_LIMITS:
            return False
        move = axis.move
        if type(move) is not PlannedMove or move.mode not in _SMART_MOVES:
            return False
        if not axis.held and tick % PROFILER_TICK_MS == 0:
            self._anticipate(axis, move, tick)
        if self.stops:
            self._at_rest(tick)
        return True

    def _anticipate(self, axis: Axis, move: PlannedMove, tick: int) -> None:
        """Hold ``move`` on the first software limit its path reaches; remember a move and limits found clear."""
        limits = self._limits(move)
        cleared = self._cleared.get(axis.number)
        if cleared is not None and cleared[0] is move and cleared[1] == limits:
            return
        crossing = self._first_crossing(move, tick)
        if crossing is None:
            self._cleared[axis.number] = (move, limits)
        else:
            self._cleared.pop(axis.number, None)
            self._stop_at(move, crossing, tick)

    def waiting(self, axis: Axis) -> int:
        """The AXISERROR bits of ``axis`` that wait on its limits rather than on ``#ONERROR``: a handler that
        returns with only these latched is not called again (AX-7), for the move may yet go on."""
        return sum(stop.bit for stop in self.stops if stop.axis == axis.number and stop.reported and self._holds(stop))

    def limits_changed(self, axis: Axis) -> None:
        """A limit or the mode of ``axis`` was written: a move held on a limit now further out goes on."""
        smart = int(axis.parameters["SOFTLIMITMODE"]) == SMART_SOFT_LIMITS
        for stop in [stop for stop in self.stops if stop.axis == axis.number]:
            written = axis.parameters[_LIMITS[stop.bit]]
            further = written > stop.limit if stop.bit == ER_FWD_SOFT else written < stop.limit
            if not self._holds(stop):  # a CANCEL ended the move: nothing is left to go on
                self.stops.remove(stop)
            elif further or not smart:
                self.stops.remove(stop)
                release(self.motion, stop.held)

    def _at_rest(self, tick: int) -> None:
        """Latch the limit and make #ONERROR pending for each held move that has come to rest; forget the
        ones a STOP, a CANCEL or an error took over."""
        for stop in list(self.stops):
            if not self._holds(stop):
                self.stops.remove(stop)
            elif not stop.reported and tick >= stop.held.ramp.end:
                stop.reported = True
                axis = self.motion.axes[stop.axis]
                axis.latch(stop.bit)
                self.raise_error(axis)

    def _holds(self, stop: _Stop) -> bool:
        """Whether ``stop``'s ramp still drives its axis: a STOP, a CANCEL or an error ends it."""
        return self.motion.axes[stop.axis].move is stop.held.ramp

    def _limits(self, move: PlannedMove) -> tuple[float, ...]:
        """What a crossing depends on besides the move: each axis's limits, mode and position origin."""
        return tuple(
            value
            for axis in (self.motion.axes[number] for number in move.axes)
            for value in (*(axis.parameters[name] for name in _LIMIT_PARAMETERS), axis.position_offset)
        )

    def _first_crossing(self, move: PlannedMove, tick: int) -> _Crossing | None:
        """The first point of the move's remaining path at which an axis in mode 4 reaches a software limit."""
        s, velocity = move.path(tick)
        ahead = _direction(move, velocity)
        if ahead == 0.0:
            return None
        end = _path_end(move, ahead)
        found: _Crossing | None = None
        for index, number in enumerate(move.axes):
            axis = self.motion.axes[number]
            p = axis.parameters
            if int(p["SOFTLIMITMODE"]) != SMART_SOFT_LIMITS:
                continue
            for bit, name in _LIMITS.items():
                at = _reach(move.geometry, index, s, ahead, p[name] + axis.position_offset, forward=bit == ER_FWD_SOFT)
                if at is not None and (at - end) * ahead <= 0.0 and (found is None or (at - found.path) * ahead < 0):
                    found = _Crossing(at, number, bit, p[name])
        return found

    def _stop_at(self, move: PlannedMove, crossing: _Crossing, tick: int) -> None:
        """Ramp ``move`` down at DECEL to rest where ``crossing`` says, and hold it there."""
        s, velocity = move.path(tick)
        master = self.motion.axes[move.axes[0]].parameters
        if (crossing.path - s) * _direction(move, velocity) <= 0.0:  # on the limit or already past it
            ramp = move.stop(tick, master["DECEL"])
        else:
            if move.length is not None:
                speed = self.motion.axes[move.axes[0]].slew_speed() if move.feedrate is None else move.feedrate
                sramp = master["SRAMP"]
            else:  # a jog runs at its own speed; a stop ramp at the speed it has; SRAMP applies to neither
                speed, sramp = abs(move.profile.final_velocity) or abs(velocity), 0.0
            profile = plan_move(crossing.path - s, speed, master["ACCEL"], master["DECEL"], velocity, sramp=sramp)
            ramp = PlannedMove(move.mode, move.axes, move.geometry, profile, tick, s)
        held = hold_on(self.motion, move, ramp)
        self.stops.append(_Stop(held, crossing.axis, crossing.bit, crossing.limit))


def _direction(move: PlannedMove, velocity: float) -> float:
    """+1 or -1 as the path position grows or shrinks from now on; 0 for a move that goes no further."""
    if move.length is not None:
        return 1.0
    heading = move.profile.final_velocity or velocity
    return math.copysign(1.0, heading) if heading else 0.0


def _path_end(move: PlannedMove, ahead: float) -> float:
    """Where the move's path ends: a positional move's length, a stop ramp's rest, a jog's never."""
    if move.length is not None:
        return move.length
    if move.profile.final_velocity == 0.0:
        return move.s_offset + move.profile.distance
    return ahead * math.inf


def _reach(geometry: Geometry, index: int, s: float, ahead: float, limit: float, *, forward: bool) -> float | None:
    """The first path position from ``s`` on (in the direction ``ahead``) at which axis ``index`` reaches
    ``limit`` travelling toward it (positive for the forward limit); ``s`` if it is past the limit and
    travelling further; None if it never gets there."""
    outward = 1.0 if forward else -1.0
    position = geometry.point(index, s)
    moving = geometry.slope(index, s) * ahead * outward  # > 0: travelling toward the limit
    if (position - limit) * outward >= 0.0 and moving > 0.0:
        return s
    if geometry.centre is None:
        slope = geometry.directions[index]
        if slope * ahead * outward <= 0.0:
            return None
        return s + (limit - position) / slope
    return _reach_on_arc(geometry, index, s, limit, outward)


def _reach_on_arc(geometry: Geometry, index: int, s: float, limit: float, outward: float) -> float | None:
    """``_reach`` on a circle: where the axis's cosine (``index`` 0) or sine (1) first takes the limit's value
    with the axis travelling outward; arcs run forward along their path."""
    radius = geometry.radius
    ratio = (limit - geometry.centre[index]) / radius
    if abs(ratio) > 1.0:
        return None
    base = math.acos(ratio) if index == 0 else math.asin(ratio)
    angles = (base, -base) if index == 0 else (base, math.pi - base)
    now = geometry.start_angle + geometry.turn * s / radius
    turns = [
        (geometry.turn * (angle - now)) % math.tau
        for angle in angles
        if geometry.slope(index, (angle - geometry.start_angle) * radius / geometry.turn) * outward > 0.0
    ]
    return s + radius * min(turns) if turns else None
