"""Motion keywords on the simulated axes: moves, GO, stops, errors and what they read (spec §3, §4).

Every handler validates first and changes state second, so a statement that
fails or has to wait for buffer space leaves the axes as they were.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING

from mintlang.analysis.rules.addressing import addressed
from mintlang.controllers import ChannelRange, ControllerProfile
from mintlang.keyworddb.model import NEXTMOVES, Controller
from mintlang.runtime.clock import Clock
from mintlang.runtime.errors import (
    INVALID_AXIS,
    INVALID_CHANNEL,
    MISSING_PARAMETER,
    TOO_MANY_VALUES,
    MintError,
    NotSimulated,
)
from mintlang.runtime.keywords import Channels, KeywordTable, Values, Writer, per_channel
from mintlang.runtime.motion.axis import (
    CONFIG_OFF,
    DRIVE_ENABLED,
    ER_ABORT,
    MD_JOG,
    MD_LINEAR,
    MD_TORQUE,
    MOTION_ERROR,
    MOTION_IN_PROGRESS,
    Axis,
    Request,
)
from mintlang.runtime.motion.moves import Geometry, PlannedMove, next_profiler_tick
from mintlang.runtime.motion.parameters import DEFAULTS, power_up
from mintlang.runtime.motion.paths import PATH_MODES, Chain, PathSegment
from mintlang.runtime.motion.profile import plan_velocity
from mintlang.runtime.ranges import check_range, ranged, table_bounds
from mintlang.runtime.scenario.stimulus import IndexPulse

if TYPE_CHECKING:  # master.py builds on this module
    from mintlang.runtime.motion.master import MasterSettings

WRONG_CONFIGURATION = 11
SMART_SOFT_LIMITS = 4  # SOFTLIMITMODE's smart mode, NextMove only (000:16057-16069)
_SOFT_LIMITS = frozenset({"SOFTLIMITFORWARD", "SOFTLIMITREVERSE", "SOFTLIMITMODE"})
_PROFILE_RATES = frozenset({"SPEED", "ACCEL", "DECEL"})
# DECELTIME = 0: a change of speed in no time, as the largest rate a Mint number holds (binary32), so every ramp
# planned at it lasts far less than a servo tick and reading DECEL gives a value, meaningless as the guide warns
INSTANT_RATE = 3.4028234663852886e38
_SWITCHES: dict[str, tuple[str, ...]] = {
    "LIMIT": ("LIMITFORWARDINPUT", "LIMITREVERSEINPUT"),
    "LIMITFORWARD": ("LIMITFORWARDINPUT",),
    "LIMITREVERSE": ("LIMITREVERSEINPUT",),
    "STOPSWITCH": ("STOPINPUT",),
    "ERRORSWITCH": ("ERRORINPUT",),
}
SAME_AXIS_TWICE = 2018


def channel_range(keyword: str, profile: ControllerProfile) -> ChannelRange | None:
    """The channels ``keyword``'s dot numbers when they are an encoder's or a DAC's rather than an axis's."""
    found = addressed(keyword, profile)
    return found[1] if found is not None and found[0] == "channel" else None


def check_channel(keyword: str, number: int, valid: ChannelRange) -> None:
    """A channel the controller lacks is error 4 (000:18522-18525), as ``mint check`` says, even where an axis has
    that number: a NextMove BX has 8 axes but encoder and DAC channels 0 to 3 (000:5613, 5621, 5624)."""
    if number not in valid:
        raise MintError(INVALID_CHANNEL, number, f"{keyword} channels: {valid}")


class Motion:
    """The axes of the controller and the keywords that drive them."""

    def __init__(self, axes: Sequence[Axis], profile: ControllerProfile, clock: Clock) -> None:
        self.axes = list(axes)
        self.profile = profile  # the controller, for what only some support (OFFSET without GO on MintDrive)
        self.clock = clock
        self.on_error: Callable[[Axis, int], None] = lambda axis, bit: None  # latch + default action + #ONERROR
        self.input_active: Callable[[int], bool] = lambda channel: False  # a digital input's state this tick
        self.auxiliary_encoder: Callable[[int], float] = lambda channel: 0.0  # AUXENCODER.channel, in counts
        self.index_pulses: dict[int, IndexPulse] = {}  # Z pulses of the scripted encoders, by axis
        self.on_default: list[Callable[[Axis], None]] = []  # each motion module's own settings back to power-up
        self.master_settings: dict[int, MasterSettings] = {}  # MASTERSOURCE and the rest, by slave axis (master.py)
        # whether an axis's live move stands still until its idle master moves (idle_masters.py): what is read of
        # it changes only after an event or the program moves that master, so its readers need no tick before
        self.stands_still: Callable[[Axis, int], bool] = lambda axis, now: False
        self.soft_limits_changed: Callable[[Axis], None] = lambda axis: None  # a move held on a limit may go on

    def index_active(self, axis: Axis) -> bool:
        """The Z pulse of ``axis`` at its current physical count (active high, HM-8 RC)."""
        pulse = self.index_pulses.get(axis.number)
        return pulse is not None and axis.measured % pulse.every_counts < pulse.width_counts

    # --------------------------------------------------------------- addressing

    def axis(self, number: int | None) -> Axis:
        if number is None:
            number = 0
        if not 0 <= number < len(self.axes):
            raise MintError(INVALID_AXIS, number, f"axes are 0 to {len(self.axes) - 1}")
        return self.axes[number]

    def axis_number(self, number: int | None) -> int:
        """The axis a write names, error 2 if the controller lacks it: ``ranged``'s check before the value."""
        return self.axis(number).number

    def addressing(self, keyword: str) -> Callable[[int | None], Axis]:
        """The axis ``keyword.n`` acts on: axis n, or for an encoder or DAC keyword the axis of channel n."""
        valid = channel_range(keyword, self.profile)
        if valid is None:
            return self.axis

        def channel_axis(channel: int | None) -> Axis:
            check_channel(keyword, 0 if channel is None else channel, valid)
            return self.axis(channel)

        return channel_axis

    def _too_many(self, channels: Channels | None) -> None:
        """More axes than the controller has is 2017 (000:19047-19052: SPEED[0,1,3] on a single axis controller)."""
        if channels is not None and len(channels) > len(self.axes):
            raise MintError(TOO_MANY_VALUES, detail=f"{len(channels)} axes on a controller with {len(self.axes)}")

    def _on_axes(self, write: Writer) -> Writer:
        """An axis parameter's writer, which first counts the axes named."""

        def checked(channels: Channels | None, values: Values) -> bool:
            self._too_many(channels)
            return write(channels, values)

        return checked

    def check_values(self, keyword: str, pairs: Sequence[tuple[Axis, float]], *, scaled: bool = True) -> None:
        """Error 3 unless each value is in ``keyword``'s range, after its axis's SCALE when scaled (000:5648-5649)."""
        limits = table_bounds(keyword, self.profile.controller)
        for axis, value in pairs:
            check_range(keyword, value, limits, axis.number, axis.scale if scaled else 1.0)

    def addressed(self, channels: Channels | None) -> list[Axis]:
        self._too_many(channels)
        numbers = channels if channels is not None else (0,)
        if len(set(numbers)) != len(numbers):
            raise MintError(SAME_AXIS_TWICE, detail="an axis is named twice")
        return [self.axis(number) for number in numbers]

    def _pairs(self, channels: Channels | None, values: Values) -> list[tuple[Axis, float]]:
        """The addressed axes with the value each gets; a skipped place leaves its axis out."""
        axes = self.addressed(channels)  # the interpreter has refused more values than axes (#2017)
        return [(axis, value) for axis, value in zip(axes, values, strict=False) if value is not None]

    # ----------------------------------------------------------------- moves

    def linear(self, keyword: str, *, relative: bool, interpolated: bool) -> Callable[[Channels | None, Values], bool]:
        """MOVEA/MOVER load one move per axis, each at its own SPEED (MP-13); VECTORA/VECTORR load one
        straight line through every addressed axis with the first as master (MP-14). Each value is in the
        keyword's range after SCALE, however far the counter then wraps (000:14617-14618)."""

        def write(channels: Channels | None, values: Values) -> bool:
            axes = self.addressed(channels)
            if interpolated:
                if None in values:
                    raise MintError(MISSING_PARAMETER, detail="a vector needs a value for each of its axes")
                axes = axes[: len(values)]  # VECTORA = 30,40 with AXES[0,1,2,3] interpolates axes 0 and 1
                if len(axes) < 2:  # VECTORR[0] = 5, VECTORA[0,1] = 5 (000:16958, 17031; 578-580)
                    raise MintError(MISSING_PARAMETER, detail="a vector needs two axes or more")
            pairs = [(axis, value) for axis, value in zip(axes, values, strict=False) if value is not None]
            self.check_values(keyword, pairs)
            for axis, _ in pairs:
                axis.require_ready()
                if (axis.move is not None and axis.move.mode not in PATH_MODES) or axis.pending_mode:
                    # 000:14541-14542 and the remedy of error 10's entry (000:18545-18547)
                    busy = f"{keyword} loads only on an idle axis or behind a linear move: check AXISMODE, PAUSE IDLE"
                    raise MintError(MOTION_IN_PROGRESS, axis.number, busy)
            if any(axis.buffer_free() <= 0 for axis, _ in pairs):
                for axis, _ in pairs:
                    self._watch_buffer(axis)
                return True
            targets = [
                axis.reference() + value * axis.scale if relative else axis.absolute(value * axis.scale)
                for axis, value in pairs
            ]
            if interpolated:
                self._load_line(axes[0], tuple(axes), tuple(targets), MD_LINEAR)
            else:
                for (axis, _), target in zip(pairs, targets, strict=True):
                    if relative or not axis.stands_at(target):  # MOVEA where it stands: no move (000:14524-14525)
                        self._load_line(axis, (axis,), (target,), MD_LINEAR)
            return False

        return write

    def _watch_buffer(self, axis: Axis) -> None:
        """A full buffer frees when the running move ends."""
        if axis.move is not None:
            self.clock.changes_at(axis.move.end)

    def _load_line(self, master: Axis, axes: tuple[Axis, ...], targets: tuple[float, ...], mode: int) -> None:
        for axis, target in zip(axes, targets, strict=True):
            axis.target = target
        segment = PathSegment(mode, axes, master.contour_mode, targets, feedrate=master.loaded_feedrate())
        request = Request(mode, segment.numbers, segment, targets, ident=master.load_ident)
        for axis in axes:
            axis.buffer.append(request)

    def start_group(self, request: Request, tick: int) -> None:
        """Start a triggered request once every axis it moves has it at the head of its buffer and is free."""
        axes = [self.axes[number] for number in request.axes]
        if any(request not in axis.buffer for axis in axes):
            self._drop_orphan(request, axes)
            return
        if any(axis.move is not None or not axis.triggered or axis.buffer[0] is not request for axis in axes):
            return
        for axis in axes:
            axis.started(axis.buffer.popleft())
            axis.triggered -= 1
        move = request.build(tick)
        if move is not None:
            for index, axis in enumerate(axes):
                axis.begin(move, index)

    def go(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        for axis in self.addressed(channels):
            axis.go()
            for request in list(axis.buffer)[: axis.triggered]:
                for number in request.axes:  # GO on one axis of a vector starts them all (MP-28)
                    other = self.axes[number]
                    if other is not axis and request in other.buffer:
                        other.triggered = max(other.triggered, list(other.buffer).index(request) + 1)
        return False

    @staticmethod
    def _drop_orphan(request: Request, axes: list[Axis]) -> None:
        """A stop or an error emptied the buffer of one axis of an interpolated move: it can never run."""
        for axis in axes:
            if request in axis.buffer:
                position = list(axis.buffer).index(request)
                del axis.buffer[position]
                if position < axis.triggered:
                    axis.triggered -= 1

    def jog(self, channels: Channels | None, values: Values) -> bool:
        """JOG: ramp to a constant speed at once, no GO (MP-16); JOG = 0 ramps down and ends the move."""
        pairs = self._pairs(channels, values)
        self.check_values("JOG", pairs)
        for axis, _ in pairs:
            axis.require_ready()
            if axis.refuses_blend():
                raise MintError(MOTION_IN_PROGRESS, axis.number, "JOG cannot blend from this move")
            if axis.torque is not None:  # only TORQUE may follow TORQUE [000:16850-16851]
                raise MintError(MOTION_IN_PROGRESS, axis.number, "in torque mode only TORQUE can be written")
            if self._blends_on_mintdrive(axis, continuing=axis.move is not None and axis.move.mode == MD_JOG):
                raise MintError(MOTION_IN_PROGRESS, axis.number, "MintDrive jogs only an idle or jogging axis")
        start = next_profiler_tick(self.clock.now)
        for axis, value in pairs:
            speed = value * axis.scale
            p = axis.parameters
            move = axis.move
            origin = axis.demand_at(start) if move is not None else axis.hold
            velocity = move.velocity(axis.index_in_move, start) if move is not None else 0.0
            axis.buffer.clear()
            axis.triggered = 0
            ramp = plan_velocity(velocity, speed, p["ACCEL"], p["DECEL"])
            if ramp.duration == 0.0 and speed == 0.0:
                axis.move = None
                axis.hold = origin
            else:
                axis.begin(
                    PlannedMove(
                        MD_JOG, (axis.number,), Geometry((origin,), (1.0,)), ramp, start, buffered=False, jog=True
                    ),
                    0,
                )
            axis.jog_speed = speed
            axis.pending_mode = MD_JOG if speed else 0
            axis.target = origin
        return False

    def torque(self, channels: Channels | None, values: Values) -> bool:
        """TORQUE: the DAC at once, servo loop off, until a stop (SL-9); it cannot blend from a
        homing cycle, a vector or a circle [000:16865-16871]."""
        pairs = self._pairs(channels, values)
        self.check_values("TORQUE", pairs, scaled=False)
        for axis, _ in pairs:
            axis.require_ready()
            if axis.refuses_blend():
                raise MintError(MOTION_IN_PROGRESS, axis.number, "TORQUE cannot blend from this move")
            if self._blends_on_mintdrive(axis, continuing=axis.torque is not None):
                raise MintError(
                    MOTION_IN_PROGRESS, axis.number, "MintDrive sets TORQUE only on an idle axis or in torque mode"
                )
        for axis, value in pairs:
            if axis.move is not None or axis.buffer:
                self.crash_group(axis)
            axis.torque = value
            axis.pending_mode = MD_TORQUE
            axis.track_measured()
            if axis.open_loop_dac is None:
                axis.dac = value  # the output changes at once, before the next servo tick
        return False

    def _blends_on_mintdrive(self, axis: Axis, *, continuing: bool) -> bool:
        """Whether a JOG or TORQUE would blend on MintDrive, which has none: the axis must be idle or already in
        that mode (``continuing``), with no move loaded behind (000:12709-12712, 16886-16889)."""
        if self.profile.controller is not Controller.MINTDRIVE:
            return False
        return bool(axis.buffer) or (not continuing and axis.busy())

    # -------------------------------------------------------------- stopping

    def stop(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        """STOP: decelerate at DECEL where the move allows it, crash stop otherwise (MP-22)."""
        tick = next_profiler_tick(self.clock.now)
        for axis in self.addressed(channels):
            if axis.torque is not None:
                self.crash_group(axis)
            else:
                self.stop_group(axis, tick, self.path_master(axis).parameters["DECEL"])
        return False

    def path_master(self, axis: Axis) -> Axis:
        """The axis whose rates an interpolated move uses: the first it names (000:3291-3292, 17004-17006)."""
        move = axis.move
        return self.axes[move.axes[0]] if move is not None and move.axes else axis

    def error_decel(self, axis: Axis) -> float:
        """The rate an error or a stop input ramps ``axis`` down at: along a path, the master's (000:10008)."""
        return self.path_master(axis).parameters["ERRORDECEL"]

    def stop_group(self, axis: Axis, tick: int, decel: float) -> None:
        """A controlled stop of ``axis`` and of every axis interpolating with it (they share one move)."""
        moving = axis.move
        stopped = axis.controlled_stop(tick, decel)
        for number in moving.axes if moving is not None else ():
            other = self.axes[number]
            if other is not axis and other.move is moving:
                other.buffer.clear()
                other.triggered = 0
                if stopped is None:
                    other.crash_stop()
                else:
                    other.ramp_down(stopped)

    def crash_group(self, axis: Axis) -> None:
        """A crash stop of ``axis`` and of every axis interpolating with it."""
        moving = axis.move
        axis.crash_stop()
        for number in moving.axes if moving is not None else ():
            other = self.axes[number]
            if other.move is moving:
                other.crash_stop()

    def cancel(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        """CANCEL: crash stop, errors cleared, demand := measured; the drive stays as it is (EV-19)."""
        for axis in self.addressed(channels):
            self.crash_group(axis)
            axis.axiserror = 0
            axis.resync()
        return False

    def reset(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        """RESET: CANCEL, then POS = 0 and the drive enabled (MP-21)."""
        for axis in self.addressed(channels):
            self.crash_group(axis)
            axis.axiserror = 0
            axis.resync()
            axis.position_offset = float(axis.measured)
            axis.enable()
        return False

    def default(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        """DEFAULT: the axis as at power-up (000:8981-9058): motion cancelled, errors cleared, POS and
        ENCODER 0, and every motion parameter, master and gearing setting back to its default."""
        for axis in self.addressed(channels):
            self.crash_group(axis)
            axis.axiserror = 0
            axis.resync()
            axis.position_offset = axis.encoder_offset = float(axis.measured)
            axis.count_from_here()  # ENCODERPRESCALE back to 1
            axis.parameters = dict(power_up(self.profile.controller))
            axis.configured()
            for reset in self.on_default:
                reset(axis)
        return False

    def abort(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        """ABORT: a motion error on every axis: crash stop, drives disabled (MP-21, AX-8)."""
        for axis in self.axes:
            self.on_error(axis, ER_ABORT)
        return False

    def all_axes(self, command: Callable[[Channels | None, tuple[float, ...]], bool]) -> Callable[..., bool]:
        return lambda channels, arguments: command(tuple(range(len(self.axes))), arguments)

    # --------------------------------------------------------------- keywords

    def register(self, table: KeywordTable) -> None:
        table.register("MOVEA", write=self.linear("MOVEA", relative=False, interpolated=False))
        table.register("MOVER", write=self.linear("MOVER", relative=True, interpolated=False))
        table.register("VECTORA", write=self.linear("VECTORA", relative=False, interpolated=True))
        table.register("VECTORR", write=self.linear("VECTORR", relative=True, interpolated=True))
        table.register("JOG", read=lambda ch: self.axis(ch).jog_speed / self.axis(ch).scale, write=self.jog)
        table.register("TORQUE", read=lambda ch: self.axis(ch).torque or 0.0, write=self.torque)
        table.register("GO", command=self.go)
        table.register("STOP", command=self.stop)
        table.register("CANCEL", command=self.cancel)
        table.register("CANCELALL", command=self.all_axes(self.cancel))
        table.register("RESET", command=self.reset)
        table.register("RESETALL", command=self.all_axes(self.reset))
        table.register("DEFAULT", command=self.default)
        table.register("DEFAULTALL", command=self.all_axes(self.default))
        table.register("ABORT", command=self.abort)
        table.register("AXES", command=self._validate_axes)
        for name in DEFAULTS:
            write = self._on_axes(per_channel(self._parameter_writer(name)))
            table.register(name, read=self._parameter_reader(name), write=write)
        for name, inputs in _SWITCHES.items():
            table.register(name, read=self._switch(inputs))
        acceltime = ranged("ACCELTIME", self.profile.controller, self._ramp_time("ACCEL"), channel=self.axis_number)
        deceltime = ranged("DECELTIME", self.profile.controller, self._ramp_time("DECEL"), channel=self.axis_number)
        table.register("ACCELTIME", write=per_channel(acceltime))  # write only (000:18915-18919)
        table.register("DECELTIME", read=self._decel_time, write=per_channel(deceltime))
        enable = ranged("DRIVEENABLE", self.profile.controller, self._enable, channel=self.axis_number)
        table.register("DRIVEENABLE", read=lambda ch: float(self.axis(ch).enabled), write=per_channel(enable))
        table.register("POS", read=self._pos, write=per_channel(self._write_pos))
        encoder = self.addressing("ENCODER")
        write_encoder = per_channel(lambda channel, value: self._write_encoder(encoder(channel), value))
        table.register("ENCODER", read=lambda ch: self._encoder(encoder(ch)), write=write_encoder)
        table.register("VEL", read=self._vel)
        velocity = self.addressing("ENCODERVEL")
        table.register("ENCODERVEL", read=lambda ch: self._encoder_velocity(velocity(ch)))
        table.register("FOLERROR", read=self._folerror)
        table.register("AXISMODE", read=lambda ch: float(self.watched(self.axis(ch)).axismode))
        table.register("AXISERROR", read=lambda ch: float(self.axis(ch).axiserror))
        table.register("AXISSTATUS", read=lambda ch: float(self.axis(ch).axisstatus))
        table.register("IDLE", read=self._idle)
        table.register("POSTARGET", read=self._postarget)
        table.register("POSREMAINING", read=self._posremaining)
        table.register("MOVEBUFFERFREE", read=lambda ch: float(self.watched(self.axis(ch)).buffer_free()))
        dac_axis = self.addressing("DAC")
        dac = per_channel(lambda channel, value: self._dac(dac_axis(channel), value))
        table.register("DAC", read=lambda ch: self.watched(dac_axis(ch), moving=True).dac, write=dac)

    def _switch(self, inputs: tuple[str, ...]) -> Callable[[int | None], float]:
        """LIMIT, LIMITFORWARD, STOPSWITCH ...: whether an assigned input is active (0 when none is assigned)."""

        def read(channel: int | None) -> float:
            axis = self.axis(channel)
            self.clock.changes_next_tick()
            for parameter in inputs:
                number = int(axis.parameters[parameter])
                if number >= 0 and self.input_active(number):
                    return 1.0
            return 0.0

        return read

    def _ramp_time(self, rate: str) -> Callable[[int | None, float], None]:
        """ACCELTIME / DECELTIME (ms): the rate that reaches the current SPEED in that time (MP-4 RC).

        The rate is not held to ACCEL's or DECEL's range: the times can set one above it (000:6258-6261,
        8971-8974). DECELTIME = 0, which its table takes (000:8953), decelerates in no time: ``INSTANT_RATE``.
        """

        def write(channel: int | None, value: float) -> None:
            axis = self.axis(channel)
            axis.parameters[rate] = axis.parameters["SPEED"] / (value / 1000.0) if value else INSTANT_RATE
            self.rates_changed(axis)

        return write

    def _decel_time(self, channel: int | None) -> float:
        """DECELTIME read (000:8944): the ms DECEL takes to bring the current SPEED to rest, so a DECEL write
        changes it (000:8920)."""
        p = self.axis(channel).parameters
        return 1000.0 * p["SPEED"] / p["DECEL"]

    def _dac(self, axis: Axis, value: float) -> None:
        """DAC = v drives the output directly, only on an axis configured off (SL-11)."""
        if axis.parameters["CONFIG"] != CONFIG_OFF:
            raise MintError(WRONG_CONFIGURATION, axis.number, "DAC can be written only when CONFIG is _cfOFF")
        if not -100.0 <= value <= 100.0:
            raise MintError(3, axis.number, f"DAC = {value:g}")
        axis.open_loop_dac = axis.dac = value  # the output changes at once, before the next servo tick

    def _validate_axes(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        self.addressed(channels)
        return False

    def _idle(self, channel: int | None) -> float:
        """IDLE, read on every tick by ``PAUSE IDLE`` loops: kept to the fewest calls."""
        axes = self.axes
        # the axis straight from the list; self.axis (error 2) only for one the controller lacks
        axis = axes[channel] if channel is not None and 0 <= channel < len(axes) else self.axis(channel)
        clock = self.clock
        if not self._standing_on_idle_master(axis, clock.now):
            clock.horizon = min(clock.horizon, clock.now + 1 if axis.plant.closed_loop else axis.next_event(clock.now))
        return 1.0 if axis.idle() else 0.0

    def _standing_on_idle_master(self, axis: Axis, now: int) -> bool:
        """Whether the live move of ``axis`` stands still until its idle master moves: nothing read of it changes
        before then."""
        move = axis.move
        return move is not None and move.live and self.stands_still(axis, now)

    def watched(self, axis: Axis, *, moving: bool = False) -> Axis:
        """Reading axis state: it may change when the move ends, or every tick while moving."""
        now = self.clock.now
        if self._standing_on_idle_master(axis, now):
            return axis
        self.clock.changes_at(axis.next_event(now))
        if moving and (axis.move is not None or axis.settling()):
            self.clock.changes_at(now + 1)
        return axis

    def _parameter_reader(self, name: str) -> Callable[[int | None], float]:
        addressing = self.addressing(name)
        return lambda channel: addressing(channel).get(name)

    def _parameter_writer(self, name: str) -> Callable[[int | None, float], None]:
        addressing = self.addressing(name)

        def write(channel: int | None, value: float) -> None:
            axis = addressing(channel)
            if name == "SOFTLIMITMODE" and value == SMART_SOFT_LIMITS and self.profile.controller not in NEXTMOVES:
                raise NotSimulated("SOFTLIMITMODE", "smart mode 4 off a NextMove, which the guide does not describe")
            if name == "CONFIG":  # it calls DEFAULT for its axis; a value it refuses resets nothing (000:8481-8483)
                check_range(name, value, axis.bounds[name], axis.number)
                if axis.enabled:
                    raise MintError(DRIVE_ENABLED, axis.number, "disable the drive (DRIVEENABLE = 0) before CONFIG")
                self.default((axis.number,), ())
            axis.set(name, value)
            if name in _PROFILE_RATES:
                self.rates_changed(axis)
            elif name in _SOFT_LIMITS:
                self.soft_limits_changed(axis)

        return write

    def rates_changed(self, master: Axis) -> None:
        """A rate of ``master`` changed: every axis of the move it leads continues on the re-planned move (MP-10)."""
        old = master.move
        if old is None or old.axes[0] != master.number:
            return
        p = master.parameters
        new = old.replan(next_profiler_tick(self.clock.now), master.slew_speed(), p["ACCEL"], p["DECEL"], p["SRAMP"])
        for number in old.axes:
            if self.axes[number].move is old:
                self.axes[number].move = new

    def _enable(self, channel: int | None, value: float) -> None:
        axis = self.axis(channel)
        if value and axis.axiserror:
            raise MintError(MOTION_ERROR, axis.number, "clear the axis error before enabling the drive")
        if value:
            axis.enable()
            return
        axis.enabled = False
        self.crash_group(axis)
        axis.disable()

    def _pos(self, channel: int | None) -> float:
        axis = self.watched(self.axis(channel), moving=True)
        return axis.position(axis.measured)

    def _write_pos(self, channel: int | None, value: float) -> None:
        axis = self.axis(channel)
        check_range("POS", value, table_bounds("POS", self.profile.controller), axis.number, axis.scale)
        if axis.busy():
            raise MintError(MOTION_IN_PROGRESS, axis.number, "POS can only be written on an idle axis")
        axis.position_offset = axis.measured - value * axis.scale

    def _encoder(self, axis: Axis) -> float:
        """The encoder's count, within 0 to ENCODERWRAP - 1 when a wrap is set (000:9813-9826), in the units
        ENCODERSCALE gives (000:9731-9735); the wrap, which its table does not mark scaled, is in counts."""
        self.watched(axis, moving=True)
        counts = axis.measured - axis.encoder_offset
        wrap = axis.parameters["ENCODERWRAP"]
        return (counts % wrap if wrap > 0 else counts) / axis.parameters["ENCODERSCALE"]

    def _write_encoder(self, axis: Axis, value: float) -> None:
        """ENCODER = v in ENCODERSCALE's units; the range is for the counts it makes, as the scale factor
        affects the encoder's range (000:9626-9627)."""
        scale = axis.parameters["ENCODERSCALE"]
        check_range("ENCODER", value, table_bounds("ENCODER", self.profile.controller), axis.number, scale)
        axis.encoder_offset = axis.measured - value * scale

    def _encoder_velocity(self, axis: Axis) -> float:
        """ENCODERVEL: the encoder's speed in ENCODERSCALE's units per second (000:9774-9776), measured as VEL
        is, over its 2 ms sample (AX-4)."""
        self.watched(axis, moving=True)
        return axis.velocity_counts() / axis.parameters["ENCODERSCALE"]

    def _vel(self, channel: int | None) -> float:
        axis = self.watched(self.axis(channel), moving=True)
        return axis.velocity_counts() / axis.scale

    def _folerror(self, channel: int | None) -> float:
        axis = self.watched(self.axis(channel), moving=True)
        return (axis.demand - axis.measured) / axis.scale

    def _postarget(self, channel: int | None) -> float:
        axis = self.axis(channel)
        if axis.axismode == MD_JOG:
            return 0.0
        return axis.position(axis.target)

    def _posremaining(self, channel: int | None) -> float:
        axis = self.watched(self.axis(channel), moving=True)
        return self._path_remaining(axis) / axis.scale

    def _path_remaining(self, axis: Axis) -> float:
        """POSREMAINING in counts; for a move of several axes, "the remaining vector length" (000:16978-16979).

        A move held at rest (SUSPEND, a stop input in mode 1) still has its distance to go; a contoured path's is
        that of the segment it is on.
        """
        move = axis.move
        if isinstance(move, (PlannedMove, Chain)) and move.buffered:
            now = self.clock.now
            left = move.to_go(now)
            if left is None:
                return 0.0
            return left if len(move.axes) > 1 else abs(move.goal(axis.index_in_move, now) - axis.demand)
        if move is None and axis.triggered and axis.buffer:
            request = axis.buffer[0]
            if len(request.axes) > 1 and request.targets is not None:
                return math.dist(request.targets, [self.axes[number].demand for number in request.axes])
        return axis.remaining()
