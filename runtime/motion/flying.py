"""Flying shears: FLY segments, and the position lock that FOLLOW's clutch modes share (spec FG-8, FG-9, MP-22).

A segment moves the slave ``S`` over ``M`` of master travel at constant
acceleration with respect to the master position, starting at the ratio the
last one ended with, so it ends at ratio ``2S/M - r0``. Segments are chained
on exact boundaries: a segment ends when the master has covered its distance,
the slave is then exactly ``S`` further, and master travel beyond the boundary
belongs to the next segment, so a chain's totals are the sums of its segments.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable
from enum import Enum

from mintlang.records import record
from mintlang.runtime.clock import NEVER
from mintlang.runtime.errors import OUT_OF_RANGE, MintError
from mintlang.runtime.keywords import Channels, KeywordTable, Values
from mintlang.runtime.motion.axis import MD_FLY, MD_OFFSET, MOTION_IN_PROGRESS, Axis, Request
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.motion.master import Link, MasterDriven, SetPoints, link, master_distance
from mintlang.runtime.motion.moves import Move
from mintlang.runtime.motion.superimposed import OffsetTrack


class StopRule(Enum):
    CRASH = "crash"
    RAMP = "ramp"
    AFTER_QUEUE = "after queue"


@record
class Shear:
    """One segment in counts: from ``ratio`` (slave counts per master count), ``slave`` over ``master`` (signed)."""

    ratio: float
    master: float
    slave: float

    @property
    def final_ratio(self) -> float:
        return 2.0 * self.slave / self.master - self.ratio

    def progress(self, travel: float) -> float:
        """The covered fraction; a master that turns back only unwinds the current segment (FG-8)."""
        return min(max(travel / self.master, 0.0), 1.0)

    def slave_at(self, travel: float) -> float:
        x = self.progress(travel)
        return self.master * x * (self.ratio + (self.final_ratio - self.ratio) * x / 2.0)

    def ratio_at(self, travel: float) -> float:
        return self.ratio + (self.final_ratio - self.ratio) * self.progress(travel)


@record
class Step:
    """A queued segment: a FLY distance, or a clutch to a ratio (``gear`` = numerator, denominator) over ``master``."""

    master: float
    slave: float | None = None
    gear: tuple[float, float] | None = None

    def shear(self, ratio: float) -> Shear:
        if self.gear is not None:
            return Shear(ratio, self.master, (ratio + self.gear[0] / self.gear[1]) / 2.0 * self.master)
        return Shear(ratio, self.master, self.slave or 0.0)


class LockedMove(MasterDriven):
    """A live move whose demand is locked to master travel: queued segments, then a gear ratio or the end.

    FLY chains end (a crash stop at the last segment's end point) when no
    segment follows; FOLLOW keeps a gear ratio after its clutch segments.
    Commands change the move at the next profiler tick, where the master is
    sampled: ``incoming`` holds them until then.
    """

    __slots__ = (
        "axes",
        "base_master",
        "base_slave",
        "buffered",
        "end",
        "gear",
        "incoming",
        "link",
        "live",
        "mode",
        "offsets",
        "points",
        "queue",
        "refill",
        "shear",
        "step",
        "stop_distance",
        "stop_rule",
        "stopping",
        "takes_fly",
    )

    def __init__(
        self,
        mode: int,
        axis: int,
        link: Link,
        origin: float,
        *,
        gear: tuple[float, float] | None,
        steps: tuple[Step, ...] = (),
        refill: Callable[[], Step | None] = lambda: None,
        stop_distance: Callable[[], float],
        stop_rule: StopRule,
        buffered: bool,
        takes_fly: bool = False,
    ) -> None:
        self.mode = mode
        self.axes = (axis,)
        self.end = NEVER
        self.buffered = buffered
        self.live = True
        self.link = link
        self.refill = refill  # the next segment from outside the move (a triggered FLY in the axis buffer)
        self.stop_distance = stop_distance  # MASTERDISTANCE now, in master counts
        self.takes_fly = takes_fly  # FOLLOWMODE 3: FLY loads into this move without GO
        self.base_slave = origin  # slave demand at the start of the current segment or gear
        self.base_master = 0.0  # master position there
        self.step: Step | None = None  # the segment running, and its kinematics from the ratio it started at
        self.shear: Shear | None = None
        self.queue: deque[Step] = deque(steps)
        self.gear = gear  # after the queue; None: the move ends there
        self.incoming: list[Callable[[float, float], None]] = []
        self.points = SetPoints(origin)
        self.stop_rule = stop_rule
        self.stopping = False
        self.offsets = OffsetTrack()  # OFFSETs superimposed on a FOLLOW

    # ------------------------------------------------------------ commands

    def changing_ratio(self) -> bool:
        """A clutch or FLY segment runs or waits, or the move ramps to rest: no OFFSET may start (000:14791-14797)."""
        return self.shear is not None or bool(self.queue) or self.stopping

    def set_gear(self, gear: tuple[float, float]) -> None:
        """An instant ratio change (FOLLOWMODE 0 and 2): the queue is dropped."""
        self.incoming.append(lambda master, slave: self._rebase(master, slave, (), gear))

    def append(self, step: Step) -> None:
        """A clutch or FLY segment after those queued (FOLLOWMODE 3); the gear afterwards is its end ratio."""

        def add(master: float, slave: float) -> None:
            self.queue.append(step)
            if self.shear is None and self.gear is not None:
                self._rebase(master, slave, tuple(self.queue), self.gear)

        self.incoming.append(add)

    def ramp_down(self, *, after_queue: bool) -> None:
        """Decelerate to rest over MASTERDISTANCE, from now or after the queued segments, then end."""
        stop = Step(self.stop_distance(), gear=(0.0, 1.0))
        self.stopping = True

        def down(master: float, slave: float) -> None:
            if after_queue and (self.queue or self.shear is not None):
                self.queue.append(stop)
                self.gear = None
            elif self.ratio(master) == 0.0:
                self._rebase(master, slave, (), None)  # already at rest: nothing to ramp
            else:
                self._rebase(master, slave, (stop,), None)

        self.incoming.append(down)

    def _rebase(self, master: float, slave: float, steps: tuple[Step, ...], gear: tuple[float, float] | None) -> None:
        ratio = self.ratio(master)
        self.base_master, self.base_slave = master, slave
        self.queue = deque(steps)
        self.gear = gear
        self._begin(self.queue.popleft() if self.queue else None, ratio)

    def _begin(self, step: Step | None, ratio: float) -> None:
        self.step = step
        self.shear = step.shear(ratio) if step is not None else None

    # -------------------------------------------------------------- motion

    def ratio(self, master: float) -> float:
        """The instantaneous ratio, slave counts per master count."""
        travel = master - self.base_master
        if self.shear is not None:
            return self.shear.ratio_at(travel)
        return self.gear[0] / self.gear[1] if self.gear is not None else 0.0

    def _position(self, master: float, tick: int) -> float:
        """Advance through completed segments to ``master`` and return the slave demand there."""
        while True:
            travel = master - self.base_master
            shear = self.shear
            if shear is None:
                if self.gear is None:
                    return self.base_slave
                numerator, denominator = self.gear
                return self.base_slave + numerator * travel / denominator
            if shear.progress(travel) < 1.0:
                return self.base_slave + shear.slave_at(travel)
            self.base_slave += shear.slave
            self.base_master += shear.master
            if self.gear is not None:  # a following move goes on at the ratio the segment ended with
                finished = self.step.gear if self.step is not None else None
                self.gear = finished if finished is not None else (shear.final_ratio, 1.0)
            self._begin(self.queue.popleft() if self.queue else self.refill(), shear.final_ratio)
            if self.shear is None and self.gear is None:
                self.end = tick

    def profiler(self, tick: int) -> None:
        master, first = self._sample_master(tick)
        points = self.points
        if first:
            self.base_master = master
            if self.queue:
                self._begin(self.queue.popleft(), 0.0)
        position = self._position(master, tick)
        incoming, self.incoming = self.incoming, []
        for change in incoming:
            if self.end == NEVER:
                change(master, position)
                position = self._position(master, tick)
        points.record(tick, position + self.offsets.total(tick))
        if self.offsets.running is None:
            self.mode &= ~MD_OFFSET

    def waits_on_master(self, now: int) -> bool:
        """A segment or gear with no command to take and no OFFSET running moves only with master travel."""
        return (
            self.end == NEVER
            and not self.incoming
            and self.offsets.running is None
            and self.points.still()
            and self.link.master.at_rest(now)
        )

    def stop(self, tick: int, decel: float) -> Move | None:
        """Per ``stop_rule``: FLY and FOLLOWMODE 2 ramp to rest over MASTERDISTANCE from the current ratio,
        FOLLOWMODE 3 after its queued segments, FOLLOWMODE 0 stops at once (MP-22, FG-6)."""
        self.offsets.cancel(tick)
        self.mode &= ~MD_OFFSET
        if self.stop_rule is StopRule.CRASH:
            return None
        self.ramp_down(after_queue=self.stop_rule is StopRule.AFTER_QUEUE)
        return self

    def replan(self, tick: int, speed: float, accel: float, decel: float, sramp: float) -> Move:
        return self


@record
class FlySegment:
    """A FLY waiting in the move buffer; built, it starts a chain that takes the following FLYs as they come."""

    step: Step
    make: Callable[[Step, int], Move]

    def __call__(self, tick: int) -> Move:
        return self.make(self.step, tick)


def register(table: KeywordTable, motion: Motion) -> None:
    def next_fly(axis: Axis) -> Callable[[], Step | None]:
        def take() -> Step | None:
            buffer = axis.buffer
            if axis.triggered and buffer and isinstance(buffer[0].build, FlySegment):
                axis.triggered -= 1
                return buffer.popleft().build.step  # type: ignore[union-attr]
            return None

        return take

    def chain(axis: Axis) -> Callable[[Step, int], Move]:
        def make(step: Step, tick: int) -> Move:
            move = LockedMove(
                MD_FLY,
                axis.number,
                link(motion, axis),
                axis.hold,
                gear=None,
                steps=(step,),
                refill=next_fly(axis),
                stop_distance=lambda: master_distance(motion, axis),
                stop_rule=StopRule.RAMP,
                buffered=True,
            )
            move.profiler(tick)
            return move

        return make

    def fly(channels: Channels | None, values: Values) -> bool:
        """FLY: a segment into the buffer (needs GO), or straight into a FOLLOWMODE 3 move (FG-8, FG-4)."""
        pairs = motion._pairs(channels, values)
        motion.check_values("FLY", pairs)  # the controller's range, after SCALE (000:10500-10510, 5647-5648)
        loads: list[tuple[Axis, Step]] = []
        for axis, value in pairs:
            axis.require_ready()
            link(motion, axis)
            distance = master_distance(motion, axis)
            if distance == 0.0:
                raise MintError(OUT_OF_RANGE, axis.number, "FLY needs a MASTERDISTANCE other than 0")
            move = axis.move
            clutch = isinstance(move, LockedMove) and move.takes_fly
            if not clutch and (
                (move is not None and move.mode != MD_FLY)
                or axis.pending_mode
                or any(request.mode != MD_FLY for request in axis.buffer)
            ):
                raise MintError(MOTION_IN_PROGRESS, axis.number, "only FLY segments can follow a FLY")
            loads.append((axis, Step(distance, slave=value * axis.scale)))
        if any(axis.buffer_free() <= 0 for axis, _ in loads if not _clutch(axis)):
            return True
        for axis, step in loads:
            move = axis.move
            if isinstance(move, LockedMove) and move.takes_fly:
                move.append(step)
            else:
                segment = FlySegment(step, chain(axis))
                axis.buffer.append(Request(MD_FLY, (axis.number,), segment, ident=axis.load_ident))
        return False

    table.register("FLY", write=fly)


def _clutch(axis: Axis) -> bool:
    return isinstance(axis.move, LockedMove) and axis.move.takes_fly
