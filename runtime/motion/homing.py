"""Homing: HOME, HOMEPOS and HOMESWITCH (spec §5, HM-1..HM-9).

A homing cycle is one live ``Move`` that reacts to the home switch and the
encoder's index pulse on every profiler tick. It runs as a chain of velocity
ramps (seek, stop, back off, creep), each planned from the position and
velocity the previous one had reached, and it ends with a crash stop on the
datum: the encoder count on which the profiler saw the deciding transition.
That count becomes ``POS`` 0, so the axis rests exactly on ``POS`` 0 and
``HOMEPOS`` keeps what ``POS`` read there before.

The switch and the index are polled at the profiler rate, as the controller's
profiler does: a back-off of ``v`` counts/s finds the switch edge within
``2 ms · v`` counts, and the 500 counts/s creep (one count per profiler tick)
finds the index edge to the count.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from enum import Enum

from mintlang.records import record
from mintlang.runtime.clock import NEVER
from mintlang.runtime.errors import OUT_OF_RANGE, MintError
from mintlang.runtime.keywords import Channels, KeywordTable, Values
from mintlang.runtime.motion.axis import MD_HOMING, MOTION_IN_PROGRESS, Axis, wrap
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.motion.moves import PROFILER_TICK_MS, Geometry, PlannedMove, completion_tick, next_profiler_tick
from mintlang.runtime.motion.profile import Profile, plan_velocity
from mintlang.runtime.scenario.stimulus import IndexPulse

NO_INPUT_SPECIFIED = 5  # _erNO_INPUT_SPECIFIED: a switch mode without HOMEINPUT [000:18526-18528]
CREEP_SPEED = 500.0  # counts/s onto the index edge (HM-4 RC: the keyword entry, not "one count per tick")
MODES = frozenset({0, 1, 2, 3, 4, 6})  # HM-1: bit 0 index, bit 1 positive, bit 2 index only

# Phases read back from HOME (HM-7)
IDLE_PHASE, SEARCH_FOR_HOME, FOUND_HOME, SEARCH_FOR_Z, FOUND_Z, CREEP = 0, 1, 2, 3, 4, 5


class Stage(Enum):
    """Where in its sequence a cycle is; several stages share a phase number."""

    SEEK = "seek"  # to the switch at HOMESPEED
    BRAKE = "brake"  # switch seen: down to rest at DECEL
    BACK_OFF = "back off"  # away from the switch at HOMESPEED/HOMEBACKOFF until it clears
    SEARCH_Z = "search z"  # on at HOMESPEED/HOMEBACKOFF until the index is active
    BRAKE_Z = "brake z"  # index seen: down to rest at DECEL
    CREEP = "creep"  # back at 500 counts/s until the index goes from active to inactive
    DONE = "done"


PHASES = {
    Stage.SEEK: SEARCH_FOR_HOME,
    Stage.BRAKE: FOUND_HOME,
    Stage.BACK_OFF: FOUND_HOME,
    Stage.SEARCH_Z: SEARCH_FOR_Z,
    Stage.BRAKE_Z: FOUND_Z,
    Stage.CREEP: CREEP,
    Stage.DONE: IDLE_PHASE,
}


@record
class Segment:
    """One ramp of the cycle: from ``origin`` counts at profiler tick ``start``, along ``profile``."""

    start: int
    origin: float
    profile: Profile

    def sample(self, tick: int) -> tuple[float, float]:
        position, velocity = self.profile.sample(max(tick - self.start, 0) / 1000.0)
        return self.origin + position, velocity

    @property
    def end(self) -> int:
        """The first profiler tick on which the ramp has reached its final velocity."""
        return completion_tick(self.start, self.profile.duration)


class HomingMove:
    """A homing cycle on one axis (HM-3, HM-4, HM-5); ``profiler`` advances it, ``demand`` samples it."""

    __slots__ = (
        "armed",
        "axes",
        "axis",
        "buffered",
        "creep_direction",
        "datum",
        "end",
        "home_input",
        "index_active",
        "live",
        "mode",
        "on_datum",
        "prior",
        "seek_direction",
        "seek_index",
        "segment",
        "stage",
        "started",
        "switch",
        "switch_active",
    )

    def __init__(
        self,
        axis: Axis,
        home: int,
        start: int,
        *,
        home_input: int,
        switch_active: Callable[[], bool],
        index_active: Callable[[], bool],
        on_datum: Callable[[float], None],
    ) -> None:
        self.mode = MD_HOMING
        self.home_input = home_input  # HOMEINPUT when HOME was written: the switch the cycle watches
        self.axes = (axis.number,)
        self.buffered = False
        self.live = True
        self.end = NEVER
        self.axis = axis
        self.seek_direction = 1.0 if home & 2 else -1.0
        self.switch = not home & 4  # modes 0-3 look for the switch first
        self.switch_active = switch_active
        self.index_active = index_active
        self.on_datum = on_datum
        self.segment = Segment(start, axis.hold, plan_velocity(0.0, 0.0, 1.0, 1.0))
        self.prior: Segment | None = None
        self.started = False
        # The axis is at rest when HOME is written, so the switch it stands on now is the one it starts on:
        # already active means back off at once [000:11469-11471].
        self.armed = self.switch and switch_active()  # the switch (creeping: the index) was seen active
        self.stage = Stage.SEARCH_Z if not self.switch else Stage.BACK_OFF if self.armed else Stage.SEEK
        self.datum = 0.0
        self.seek_index = bool(home & 5)  # modes 1, 3, 4, 6 end on the index
        # The index is searched for away from the switch (modes 1, 3) or in the seek direction (4, 6);
        # the creep comes back the other way.
        self.creep_direction = self.seek_direction if self.switch else -self.seek_direction

    @property
    def phase(self) -> int:
        return PHASES[self.stage]

    def waiting_for(self, pulse: IndexPulse | None) -> str | None:
        """What the cycle still waits to see, for a run stopped while it searches; None past the searches."""
        if self.stage is Stage.SEEK:
            return f"seeks its home switch, input {self.home_input}, which has not turned active"
        if self.stage is Stage.BACK_OFF:
            return f"backs off its home switch, input {self.home_input}, which has not turned inactive"
        if self.stage is not Stage.SEARCH_Z:
            return None
        axis = self.axis.number
        if pulse is None:
            return f"searches for its encoder's index pulse, which no scenario gives it (REM @sim index {axis} every N)"
        speed = self._backoff_speed()
        travel = math.ceil(speed * PROFILER_TICK_MS / 1000.0)  # counts between two polls of the index
        if pulse.width_counts >= travel:
            return "searches for its encoder's index pulse"
        count = "count" if pulse.width_counts == 1 else "counts"
        return (
            f"searches for its encoder's index pulse, {pulse.width_counts} {count} wide, which it passes between two"
            f" polls at {speed:g} counts/s ({travel} counts every {PROFILER_TICK_MS} ms): make it at least {travel}"
            f" counts wide (REM @sim index {axis} every {pulse.every_counts} width {travel})"
        )

    # ------------------------------------------------------------- Move protocol

    def demand(self, index: int, tick: int) -> float:
        if tick >= self.end:
            return self.datum
        return self._segment_at(tick).sample(tick)[0]

    def velocity(self, index: int, tick: int) -> float:
        if tick >= self.end:
            return 0.0
        return self._segment_at(tick).sample(tick)[1]

    def profiler(self, tick: int) -> None:
        if tick < self.segment.start or self.stage is Stage.DONE:
            return
        if not self.started:
            self._begin(tick)
        else:
            self._advance(tick)

    def stop(self, tick: int, decel: float) -> PlannedMove:
        """STOP (or an error's ramp) brings the axis to rest at ``decel``; the cycle is abandoned, POS kept."""
        position, velocity = self._segment_at(tick).sample(tick)
        ramp = plan_velocity(velocity, 0.0, decel, decel)
        return PlannedMove(MD_HOMING, self.axes, Geometry((position,), (1.0,)), ramp, tick, buffered=False)

    def replan(self, tick: int, speed: float, accel: float, decel: float, sramp: float) -> HomingMove:
        return self  # ACCEL and DECEL are read as each ramp is planned; SPEED and SRAMP do not apply (HM-2)

    # ------------------------------------------------------------------ sequence

    def _begin(self, tick: int) -> None:
        """The first profiler tick: off toward the switch, away from it, or toward the index."""
        self.started = True
        if self.stage is Stage.SEEK:
            self._ramp(tick, self.seek_direction * self.axis.parameters["HOMESPEED"])
        elif self.stage is Stage.BACK_OFF:
            self._ramp(tick, -self.seek_direction * self._backoff_speed())
        else:
            self._ramp(tick, self.seek_direction * self._backoff_speed())

    def _advance(self, tick: int) -> None:
        stage = self.stage
        if stage is Stage.SEEK:
            if self.switch_active():
                self.stage = Stage.BRAKE
                self.armed = True
                self._ramp(tick, 0.0)
        elif stage is Stage.BRAKE:
            if not self.switch_active():
                self.armed = False  # went through the switch while braking: it must be seen again (HM-3 5)
            if tick >= self.segment.end:
                self.stage = Stage.BACK_OFF
                self._ramp(tick, -self.seek_direction * self._backoff_speed())
        elif stage is Stage.BACK_OFF:
            if self.switch_active():
                self.armed = True
            elif self.armed:
                if not self.seek_index:
                    self._finish(tick)
                    return
                self.stage = Stage.SEARCH_Z  # HM-4 RC: the index counts once the switch has cleared
                self._advance(tick)
        elif stage is Stage.SEARCH_Z:
            if self.index_active():
                self.stage = Stage.BRAKE_Z
                self._ramp(tick, 0.0)
        elif stage is Stage.BRAKE_Z:
            if tick >= self.segment.end:
                self.stage = Stage.CREEP
                self.armed = self.index_active()
                self._ramp(tick, self.creep_direction * CREEP_SPEED)
        elif stage is Stage.CREEP:
            if self.index_active():
                self.armed = True
            elif self.armed:
                self._finish(tick)

    def _ramp(self, tick: int, velocity: float) -> None:
        """Continue from where the axis is at ``tick`` toward ``velocity`` at ACCEL/DECEL (SRAMP ignored, HM-2)."""
        position, current = self.segment.sample(tick)
        p = self.axis.parameters
        self.prior = self.segment
        self.segment = Segment(tick, position, plan_velocity(current, velocity, p["ACCEL"], p["DECEL"]))

    def _finish(self, tick: int) -> None:
        """Crash stop on the count the transition was seen at; it becomes POS 0 (HM-3 RC, HM-6)."""
        axis = self.axis
        self.datum = float(axis.measured)
        self.on_datum(wrap(self.datum - axis.position_offset))
        axis.position_offset = self.datum
        axis.target = self.datum
        self.stage = Stage.DONE
        self.end = tick

    def _segment_at(self, tick: int) -> Segment:
        """The ramp in force at ``tick``; the servo loop may look back past the latest ramp's start."""
        if tick < self.segment.start and self.prior is not None:
            return self.prior
        return self.segment

    def _backoff_speed(self) -> float:
        p = self.axis.parameters
        return p["HOMESPEED"] / p["HOMEBACKOFF"]


class Homing:
    """The homing keywords of a controller and the last HOMEPOS of each axis."""

    def __init__(self, motion: Motion) -> None:
        self.motion = motion
        self.homepos: dict[int, float] = {}  # counts, before the datum became 0

    def write_home(self, channels: Channels | None, values: Values) -> bool:
        """HOME[axes] = mode: checked on every axis first, then every cycle starts on the next profiler tick."""
        motion = self.motion
        pairs = motion._pairs(channels, values)
        for axis, value in pairs:
            if value not in MODES:
                raise MintError(OUT_OF_RANGE, axis.number, f"HOME = {value:g}")
            axis.require_ready()
            if axis.busy() or axis.triggered:
                raise MintError(MOTION_IN_PROGRESS, axis.number, "HOME needs an idle axis")
            if not int(value) & 4 and axis.parameters["HOMEINPUT"] < 0:
                raise MintError(NO_INPUT_SPECIFIED, axis.number, "set HOMEINPUT before homing on a switch")
        start = next_profiler_tick(motion.clock.now)
        for axis, value in pairs:
            channel = int(axis.parameters["HOMEINPUT"])
            move = HomingMove(
                axis,
                int(value),
                start,
                home_input=channel,
                switch_active=lambda channel=channel: motion.input_active(channel),
                index_active=lambda axis=axis: motion.index_active(axis),
                on_datum=lambda counts, number=axis.number: self.homepos.__setitem__(number, counts),
            )
            axis.begin(move, 0)
            axis.pending_mode = MD_HOMING
            axis.target = axis.hold
        return False

    def read_home(self, channel: int | None) -> float:
        """The phase of the cycle (HM-7); it can change on any tick while one runs."""
        axis = self.motion.axis(channel)
        move = axis.move
        if isinstance(move, HomingMove):
            self.motion.clock.changes_next_tick()
            return float(move.phase)
        return float(IDLE_PHASE)

    def read_homepos(self, channel: int | None) -> float:
        axis = self.motion.axis(channel)
        return self.homepos.get(axis.number, 0.0) / axis.scale

    def read_homeswitch(self, channel: int | None) -> float:
        """The active state of the axis's HOMEINPUT; 0 when it has none."""
        axis = self.motion.axis(channel)
        self.motion.clock.changes_next_tick()
        home_input = int(axis.parameters["HOMEINPUT"])
        return float(home_input >= 0 and self.motion.input_active(home_input))


def still_homing(motion: Motion) -> tuple[str, ...]:
    """Each axis whose cycle is still searching, with what it waits for: why a run that hit a limit while
    a PAUSE waits for the cycle to end may never have ended (a switch or an index no scenario gives)."""
    found = []
    for axis in motion.axes:
        move = axis.move
        if isinstance(move, HomingMove):
            waiting = move.waiting_for(motion.index_pulses.get(axis.number))
            if waiting is not None:
                found.append(f"axis {axis.number} is still homing: it {waiting}")
    return tuple(found)


def register(table: KeywordTable, motion: Motion) -> None:
    homing = Homing(motion)
    table.register("HOME", read=homing.read_home, write=homing.write_home)
    table.register("HOMEPOS", read=homing.read_homepos)
    table.register("HOMESWITCH", read=homing.read_homeswitch)
