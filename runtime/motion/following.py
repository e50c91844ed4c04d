"""Encoder following: FOLLOW, FOLLOWDENOM and FOLLOWMODE (spec FG-3..FG-6).

FOLLOW starts at the next profiler tick without GO. Position-locked modes (0,
2, 3) keep the slave demand at ``start + sum(ratio * master travel)``; each
ratio is kept as FOLLOW and FOLLOWDENOM so that the product is computed once
per ratio from the master travel since the ratio began, exact in counts. The
clutch modes ramp with flying-shear segments over MASTERDISTANCE (flying.py).
Mode 1 locks velocity instead: the slave approaches ratio x master velocity at
its own ACCEL and DECEL, so it can slip.
"""

from __future__ import annotations

from mintlang.records import record
from mintlang.runtime.clock import NEVER
from mintlang.runtime.errors import OUT_OF_RANGE, MintError
from mintlang.runtime.keywords import KeywordTable, per_channel
from mintlang.runtime.motion.axis import MD_FOLLOW, MD_OFFSET, MOTION_IN_PROGRESS, Axis
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.motion.flying import LockedMove, Step, StopRule
from mintlang.runtime.motion.master import Link, MasterDriven, SetPoints, link, master_distance
from mintlang.runtime.motion.moves import PROFILER_TICK_MS, Move
from mintlang.runtime.motion.superimposed import OffsetTrack
from mintlang.runtime.ranges import check_range, table_bounds

NO_RAMP, RAMP, CLUTCH, CONTINUOUS_CLUTCH = 0, 1, 2, 3
TICK_S = PROFILER_TICK_MS / 1000.0
RATIO_MIN, RATIO_MAX = -128.0, 127.0


def approach(velocity: float, target: float, up: float, down: float) -> float:
    """One profiler tick towards ``target``: speeding up by ``up``, slowing (through rest) by ``down``."""
    if velocity == target:
        return velocity
    if (velocity > 0.0 and target < velocity) or (velocity < 0.0 and target > velocity):
        if velocity > 0.0:
            return max(target, 0.0, velocity - down)
        return min(target, 0.0, velocity + down)
    return min(target, velocity + up) if target > velocity else max(target, velocity - up)


class VelocityLockedMove(MasterDriven):
    """FOLLOWMODE 1: slave velocity follows ratio x master velocity at the slave's ACCEL and DECEL (FG-4)."""

    __slots__ = (
        "axes",
        "axis",
        "buffered",
        "decel",
        "end",
        "link",
        "live",
        "master",
        "mode",
        "offsets",
        "points",
        "ratio",
        "speed",
        "stopping",
    )

    def __init__(self, axis: Axis, link: Link, ratio: float) -> None:
        self.mode = MD_FOLLOW
        self.axes = (axis.number,)
        self.end = NEVER
        self.buffered = False
        self.live = True
        self.link = link
        self.axis = axis
        self.ratio = ratio  # slave counts per master count
        self.speed = 0.0  # slave demand velocity, counts/s
        self.master = 0.0
        self.points = SetPoints(axis.hold)
        self.stopping = False
        self.decel = 0.0
        self.offsets = OffsetTrack()  # OFFSETs superimposed on it

    def profiler(self, tick: int) -> None:
        master, first = self._sample_master(tick)
        points = self.points
        if first:
            self.master = master
        travel = master - self.master
        self.master = master
        p = self.axis.parameters
        target = 0.0 if self.stopping else self.ratio * travel / TICK_S
        down = (self.decel if self.stopping else p["DECEL"]) * TICK_S
        self.speed = approach(self.speed, target, p["ACCEL"] * TICK_S, down)
        locked = self.speed == target and not self.stopping
        step = self.ratio * travel if locked else self.speed * TICK_S
        points.record(tick, points.position + step + self.offsets.increment(tick))
        if self.offsets.running is None:
            self.mode &= ~MD_OFFSET
        if self.stopping and self.speed == 0.0:
            self.end = tick

    def waits_on_master(self, now: int) -> bool:
        """At rest with no OFFSET running, it moves only when the master does."""
        return (
            self.end == NEVER
            and self.speed == 0.0
            and self.offsets.running is None
            and self.points.still()
            and self.link.master.at_rest(now)
        )

    def stop(self, tick: int, decel: float) -> Move | None:
        """Ramp to rest at ``decel`` (FG-6 RC: DECEL for STOP, ERRORDECEL for an error)."""
        self.stopping = True
        self.decel = decel
        self.offsets.cancel(tick)
        self.mode &= ~MD_OFFSET
        return self

    def replan(self, tick: int, speed: float, accel: float, decel: float, sramp: float) -> Move:
        return self  # ACCEL and DECEL are read on every tick


@record(frozen=False)
class FollowSettings:
    value: float = 0.0  # FOLLOW as last written
    denominator: float = 1.0
    mode: int = NO_RAMP


def _following(axis: Axis) -> LockedMove | VelocityLockedMove | None:
    move = axis.move
    if isinstance(move, (LockedMove, VelocityLockedMove)) and move.mode & MD_FOLLOW:
        return move
    return None


def register(table: KeywordTable, motion: Motion) -> None:
    state = [FollowSettings() for _ in motion.axes]

    def default(axis: Axis) -> None:
        state[axis.number] = FollowSettings()

    motion.on_default.append(default)

    def follow(channel: int | None, value: float) -> None:
        """FOLLOW = ratio: start following, or change the ratio of the running FOLLOW (FG-3, FG-4)."""
        axis = motion.axis(channel)
        settings = state[axis.number]
        if not RATIO_MIN <= value <= RATIO_MAX:
            raise MintError(OUT_OF_RANGE, axis.number, f"FOLLOW = {value:g}")
        axis.require_ready()
        running = _following(axis)
        if running is not None and running.stopping:
            raise MintError(MOTION_IN_PROGRESS, axis.number, "the FOLLOW is stopping")
        if running is None and axis.busy():
            raise MintError(MOTION_IN_PROGRESS, axis.number, "FOLLOW needs an idle axis")
        master = link(motion, axis)
        gear = (value * master.slave_per_master, settings.denominator)
        if isinstance(running, VelocityLockedMove):
            running.ratio = gear[0] / gear[1]
        elif running is not None:
            if settings.mode == CONTINUOUS_CLUTCH:
                if running.offsets.running is not None:  # no ratio change while an OFFSET runs (000:14796-14797)
                    raise MintError(MOTION_IN_PROGRESS, axis.number, "the ratio cannot change during an OFFSET")
                running.append(Step(master_distance(motion, axis), gear=gear))
            else:
                running.set_gear(gear)
        else:
            axis.begin(start(axis, master, gear, settings.mode), 0)
            axis.pending_mode = MD_FOLLOW
            axis.target = axis.hold
        settings.value = value

    def start(axis: Axis, master: Link, gear: tuple[float, float], mode: int) -> Move:
        if mode == RAMP:
            return VelocityLockedMove(axis, master, gear[0] / gear[1])
        clutch = mode in (CLUTCH, CONTINUOUS_CLUTCH)
        rule = {NO_RAMP: StopRule.CRASH, CLUTCH: StopRule.RAMP}.get(mode, StopRule.AFTER_QUEUE)
        return LockedMove(
            MD_FOLLOW,
            axis.number,
            master,
            axis.hold,
            gear=gear,
            steps=(Step(master_distance(motion, axis), gear=gear),) if clutch else (),
            stop_distance=lambda: master_distance(motion, axis),
            stop_rule=rule,
            buffered=False,
            takes_fly=mode == CONTINUOUS_CLUTCH,
        )

    denominators = table_bounds("FOLLOWDENOM", table.controller)  # whole numbers 1 to 128 (000:10798)

    def denominator(channel: int | None, value: float) -> None:
        axis = motion.axis(channel)
        check_range("FOLLOWDENOM", value, denominators, axis.number)
        state[axis.number].denominator = value  # used by the next FOLLOW (FG-3)

    modes = table_bounds("FOLLOWMODE", table.controller)  # its four modes: whole numbers 0 to 3 (000:10846)

    def follow_mode(channel: int | None, value: float) -> None:
        axis = motion.axis(channel)
        check_range("FOLLOWMODE", value, modes, axis.number)
        if _following(axis) is not None:
            raise MintError(MOTION_IN_PROGRESS, axis.number, "FOLLOWMODE cannot change while following")
        state[axis.number].mode = int(value)

    table.register("FOLLOW", read=lambda ch: state[motion.axis(ch).number].value, write=per_channel(follow))
    table.register(
        "FOLLOWDENOM", read=lambda ch: state[motion.axis(ch).number].denominator, write=per_channel(denominator)
    )
    table.register(
        "FOLLOWMODE", read=lambda ch: float(state[motion.axis(ch).number].mode), write=per_channel(follow_mode)
    )
