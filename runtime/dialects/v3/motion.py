"""Mint v3 motion keywords: the v4 runtime's axes under their v3 names, with v3's own rules.

What differs from v4 (each with its line in the v3 guide):

* power-up values: SPEED 40000, ACCEL and DECEL 300000, HMSPEED 40000, MFOLERR
  and IDLE 16000 counts (001:11797, 5645, 7189, 8632, 9989, 8741);
* writing ACCEL (or ACCELTIME) also writes DECEL unless bit 0 of AXISCON is set
  (001:5662, 5728, 7196-7198); the other AXISCON bits are not simulated;
* SCALE takes whole numbers, rounding a fraction down (001:11610);
* values are range-checked as the keyword tables give them for SCALE 1 (V3-5);
* MODE and ERROR read one code, not a bit pattern (001:10038-10061, 4995-5003);
* GO waits while a move runs on an axis with another move behind it (001:3404-3412);
* a motion error on one axis aborts the others and switches the common amplifier
  enable off; CANCEL and RESET switch it on again (001:4995-5006, 5572, 7567) (V3-6);
* RESET also clears the outputs and TIME and sets IMASK to 255 (001:11409-11444);
* CONFIG = _servo or _off issues a RESET and restores the rates (001:6931-6939);
* the dedicated home, limit and stop inputs (``controllers.py``) are the axes' HOMEINPUT,
  limit inputs (one for both directions, 001:4600) and STOPINPUT: HOME reads its switch
  and does nothing when the switch is already open (001:3470-3509); DISLIMIT and ENLIMIT
  switch the limits off and on (001:7433-7470); the stop input ramps the moves down at
  DECEL and lets them go on when it clears, or (STOPMODE 2) cancels them (001:4542-4560,
  11894-11929);
* SERVOFF is TORQUE = 0, as the guide says (001:11700-11712), with MODE 1 and "Servo off"
  for a move; SERVOC restores the servo where the axis is, as its STOP (001:11629-11662);
  ENABLE switches the common amplifier enable (001:7547-7576).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from types import MappingProxyType

from mintlang.runtime.dialects.v3.controllers import HOME_INPUT, LIMIT_INPUT, STOP_INPUT
from mintlang.runtime.errors import MintError, NotSimulated
from mintlang.runtime.keywords import Channels, KeywordAccess, KeywordTable, Values, per_channel
from mintlang.runtime.motion.axis import (
    ER_ABORT,
    ER_ERROR_INPUT,
    ER_FOLLOWING,
    ER_FWD_HARD,
    ER_REV_HARD,
    MD_CIRCULAR,
    MD_FLY,
    MD_FOLLOW,
    MD_HOMING,
    MD_JOG,
    MD_LINEAR,
    MD_OFFSET,
    MD_TORQUE,
    Axis,
)
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.motion.moves import next_profiler_tick
from mintlang.runtime.ranges import UNBOUNDED

OUT_OF_RANGE = 3
SERVO_OFF = 40  # the v4 error for a drive that is off, which v3 reports as "Servo off"
DECEL_ENABLED = 1  # AXISCON bit 0 (001:6024)
SCALE_LIMIT = 32000.0  # CONFLICT: 65000 (001:960), 32000 (001:97), 3200 (001:11592); the table printed twice
CONFIG_OFF, CONFIG_SERVO = 0, 1

POWER_UP: Mapping[str, float] = MappingProxyType(
    {
        "SPEED": 40_000.0,
        "ACCEL": 300_000.0,
        "DECEL": 300_000.0,
        "HOMESPEED": 40_000.0,
        "HOMEBACKOFF": 10.0,
        "FOLERRORFATAL": 16_000.0,
        "IDLEPOS": 16_000.0,
        "DACLIMITMAX": 100.0,
    }
)
"""The v3 power-up values of the v4 parameters, in counts (001 chapter 10 tables); the others are v4's."""

RATES = ("SPEED", "ACCEL", "DECEL", "HOMESPEED")  # what CONFIG restores (001:6931)
LIMITS_ON, LIMITS_OFF = 1.0, 0.0  # LIMITMODE: crash stop (and the v3 abort), or ignore
STOPMODES = {1.0: 1.0, 2.0: 2.0}  # STOPMODE -> STOPINPUTMODE: ramp and hold, or cancel


def power_up(axis: int) -> dict[str, float]:
    """The v4 parameters of v3 axis ``axis`` at power-up: v3's rates and its dedicated inputs."""
    inputs = {"HOMEINPUT": HOME_INPUT + axis, "LIMITFORWARDINPUT": LIMIT_INPUT + axis}
    return {**POWER_UP, **inputs, "LIMITREVERSEINPUT": LIMIT_INPUT + axis, "STOPINPUT": STOP_INPUT}


RENAMED: Mapping[str, str] = MappingProxyType(
    {
        "GAIN": "KPROP",
        "KINTRANGE": "KINTLIMIT",
        "HMSPEED": "HOMESPEED",
        "BACKOFF": "HOMEBACKOFF",
        "MFOLERR": "FOLERRORFATAL",
        "CURRLIMIT": "DACLIMITMAX",
        "IDLE": "IDLEPOS",
    }
)
"""v3 names of v4 axis parameters (001 chapter 10; spec M-REN); IDLE only when written (001:8762-8770)."""

# v3 name -> (lowest, highest, scaled): the keyword tables' ranges, in counts for the scaled ones
RANGES: Mapping[str, tuple[float, float, bool]] = MappingProxyType(
    {
        "ACCEL": (1000.0, 8_388_607.0, True),
        "DECEL": (1000.0, 8_388_607.0, True),
        "SPEED": (0.0, 5_300_000.0, True),
        "HMSPEED": (2.0, 5_300_000.0, True),
        "JOG": (-5_300_000.0, 5_300_000.0, True),
        "MFOLERR": (0.0, 32_767.0, True),
        "IDLE": (0.0, 16_000.0, True),
        "BACKOFF": (1.0, 100.0, False),
        "CURRLIMIT": (1.0, 100.0, False),
        "GAIN": (0.0, 255.0, False),
        "KINT": (0.0, 255.0, False),
        "KINTRANGE": (0.0, 255.0, False),
        "KVEL": (0.0, 255.0, False),
        "KVELFF": (0.0, 255.0, False),
        "TORQUE": (-100.0, 100.0, False),
        "ACCELTIME": (2.0, 32_000.0, False),
    }
)

_MODES: Mapping[int, float] = MappingProxyType(
    {0: 0.0, MD_LINEAR: 2.0, MD_JOG: 3.0, MD_CIRCULAR: 4.0, MD_TORQUE: 6.0, MD_HOMING: 7.0}
    | {MD_OFFSET: 8.0, MD_FOLLOW: 9.0, MD_FLY: 15.0}
)
"""AXISMODE bits -> MODE codes (001:10038-10061)."""

_ERRORS: tuple[tuple[int, float], ...] = (
    (ER_FOLLOWING, 2.0),
    (ER_FWD_HARD | ER_REV_HARD, 3.0),
    (ER_ERROR_INPUT, 11.0),
    (ER_ABORT, 1.0),
)
"""AXISERROR bits -> ERROR codes (001:4995-5003): the axis's own error before the abort it passed on."""


class V3Motion:
    """The v3 axis keywords, on top of the v4 ``Motion`` and the v4 table's handlers."""

    def __init__(self, motion: Motion, v4: KeywordTable) -> None:
        self.motion = motion
        self.v4 = v4
        self.axiscon = [0] * len(motion.axes)
        self.servo_off: set[int] = set()  # axes SERVOFF put in torque mode (MODE 1 while it lasts)
        self.on_reset: list[Callable[[], None]] = []  # what RESET clears besides the axes (outputs, TIME, IMASK)
        checked_here = (
            {RENAMED.get(name, name) for name in RANGES} & set(motion.axes[0].bounds) if motion.axes else set()
        )
        for axis in motion.axes:
            axis.bounds.update(dict.fromkeys(checked_here, UNBOUNDED))  # v3's ranges, not the v4 machine's
            self._power_up(axis)

    @staticmethod
    def _power_up(axis: Axis) -> None:
        for name, value in power_up(axis.number).items():
            axis.set(name, value)

    def _access(self, name: str) -> KeywordAccess:
        access = self.v4.get(name)
        assert access is not None, name
        return access

    # ---------------------------------------------------------------- ranges

    def _ranged(self, name: str, write_one: Callable[[int | None, float], None]) -> Callable[[int | None, float], None]:
        """``write_one`` for values in the v3 range of ``name`` (a scaled one in counts, 001:13136-13138)."""
        low, high, scaled = RANGES[name]

        def write(channel: int | None, value: float) -> None:
            counts = value * self.motion.axis(channel).scale if scaled else value
            if not low <= counts <= high:
                raise MintError(OUT_OF_RANGE, channel, f"{name} = {value:g}")
            if name == "SPEED" and value == 0:
                raise NotSimulated(
                    "SPEED", "a speed of 0, which v3 accepts: the guide does not say what a move does then"
                )
            write_one(channel, value)

        return write

    def _v4_writer(self, name: str) -> Callable[[int | None, float], None]:
        """The v4 writer of ``name`` for one axis."""
        write = self._access(name).write
        assert write is not None, name

        def write_one(channel: int | None, value: float) -> None:
            write(None if channel is None else (channel,), (value,))

        return write_one

    # ---------------------------------------------------------------- keywords

    def register(self, table: KeywordTable) -> None:
        for v3, v4 in RENAMED.items():
            access = self._access(v4)
            read = access.read if v3 != "IDLE" else self._access("IDLE").read
            table.register(v3, read=read, write=self._writer(v3, v4))
        for name in ("SPEED", "KINT", "KVEL", "KVELFF"):
            table.register(name, read=self._access(name).read, write=self._writer(name, name))
        for name in ("TORQUE", "JOG"):
            table.register(name, read=self._access(name).read, write=self._servo_on(self._writer(name, name)))
        for name in ("AXES", "POS", "ENCODER", "STOP", "FASTPOS", "VEL", "ABORT"):
            table.alias(name, self._access(name))
        table.alias("FOLERR", self._access("FOLERROR"))
        table.alias("FASTENC", self._access("FASTENCODER"))
        target = self._access("POSTARGET").read
        for name in ("MOVEA", "MOVER"):
            table.register(name, read=target, write=self._servo_on(self._v4_write(name)))
        for name in ("VECTORA", "VECTORR"):
            table.register(name, write=self._servo_on(self._v4_write(name)))
        table.register("SERVOFF", command=self._servoff)
        table.register("SERVOC", command=self._servoc)
        table.register("ENABLE", write=per_channel(self._enable))
        table.register("ACCEL", read=self._access("ACCEL").read, write=per_channel(self._accel))
        table.register("DECEL", read=self._access("DECEL").read, write=per_channel(self._ranged("DECEL", self._decel)))
        table.register("ACCELTIME", write=per_channel(self._ranged("ACCELTIME", self._acceltime)))
        table.register(
            "AXISCON",
            read=lambda ch: float(self.axiscon[self.motion.axis(ch).number]),
            write=per_channel(self._write_axiscon),
        )
        table.register("SCALE", read=self._access("SCALE").read, write=per_channel(self._scale))
        table.register("MODE", read=self._mode)
        table.register("ERROR", read=self._error)
        table.register("GO", command=self._go)
        table.register("CANCEL", command=self._cancel)
        table.register("DISLIMIT", command=self._limits(LIMITS_OFF))
        table.register("ENLIMIT", command=self._limits(LIMITS_ON))
        table.register("HOME", read=self._access("HOMESWITCH").read, write=self._home)
        table.register("STOPMODE", read=self._stopmode, write=per_channel(self._write_stopmode))
        table.register("RESET", command=self._reset)
        table.register("DEFAULT", command=self._default)
        table.register("ZERO", command=self._zero)
        table.register("CONFIG", read=self._access("CONFIG").read, write=per_channel(self._config))
        table.register("CONTON", command=self._contouring(1.0))
        table.register("CONTOFF", command=self._contouring(0.0))
        table.register("OFFSET", read=self._remaining)
        table.register("CIRCLEA", write=self._servo_on(self._circle("CIRCLEA")))
        table.register("CIRCLER", write=self._servo_on(self._circle("CIRCLER")))
        table.register("RAMP", read=lambda ch: 0.0, write=per_channel(self._ramp))

    def _v4_write(self, name: str) -> Callable[[Channels | None, Values], bool]:
        write = self._access(name).write
        assert write is not None, name
        return write

    def _writer(self, v3: str, v4: str) -> Callable[[Channels | None, Values], bool]:
        write_one = self._v4_writer(v4)
        return per_channel(self._ranged(v3, write_one) if v3 in RANGES else write_one)

    # ------------------------------------------------------------ rates

    def _accel(self, channel: int | None, value: float) -> None:
        """ACCEL, and DECEL with it unless AXISCON bit 0 is set (001:5662)."""
        self._ranged("ACCEL", self._v4_writer("ACCEL"))(channel, value)
        self._follow_accel(channel)

    def _follow_accel(self, channel: int | None) -> None:
        axis = self.motion.axis(channel)
        if not self.axiscon[axis.number] & DECEL_ENABLED:
            self._decel(channel, axis.get("ACCEL"))

    def _decel(self, channel: int | None, value: float) -> None:
        """DECEL, which the stop input ramps down at too (001:7214)."""
        self._v4_writer("DECEL")(channel, value)
        self._v4_writer("ERRORDECEL")(channel, value)

    def _acceltime(self, channel: int | None, value: float) -> None:
        """ACCELTIME writes ACCEL, so DECEL follows as for ACCEL (001:5728)."""
        self._v4_writer("ACCELTIME")(channel, value)
        self._follow_accel(channel)

    def _write_axiscon(self, channel: int | None, value: float) -> None:
        axis = self.motion.axis(channel)
        if value != int(value) or not 0 <= value <= 255:
            raise MintError(OUT_OF_RANGE, axis.number, f"AXISCON = {value:g}")
        if int(value) & ~DECEL_ENABLED:
            raise NotSimulated("AXISCON", "bits 1 to 7 (the encoder board, following error off, MOVER's target)")
        self.axiscon[axis.number] = int(value)

    def _scale(self, channel: int | None, value: float) -> None:
        """SCALE takes whole numbers: a fraction is rounded down (001:11610), then 1 to 32000."""
        whole = float(math.floor(value))
        if not 1 <= whole <= SCALE_LIMIT:
            raise MintError(OUT_OF_RANGE, channel, f"SCALE = {value:g}")
        self._v4_writer("SCALE")(channel, whole)

    def _ramp(self, channel: int | None, value: float) -> None:
        """RAMP 0 is the trapezoid; the guide does not give the shape of the others (001:11212-11236)."""
        if value != 0:
            raise NotSimulated("RAMP", "an S-ramp (RAMP other than 0)")

    # ------------------------------------------------------------ reading

    def _mode(self, channel: int | None) -> float:
        axis = self.motion.axis(channel)
        if axis.number in self.servo_off and axis.torque is not None:
            return 1.0  # _servoff (001:11700)
        bits = int(self._read("AXISMODE", channel))
        if bits not in _MODES:
            raise NotSimulated("MODE", f"the v4 motion modes {bits}, which have no v3 code")
        return _MODES[bits]

    def _error(self, channel: int | None) -> float:
        bits = int(self._read("AXISERROR", channel))
        return next((code for mask, code in _ERRORS if bits & mask), 0.0)

    def _remaining(self, channel: int | None) -> float:
        """Reading OFFSET gives the rest of the move, always positive (001:3226-3241)."""
        return abs(self._read("POSREMAINING", channel))

    def _read(self, name: str, channel: int | None) -> float:
        read = self._access(name).read
        assert read is not None, name
        return read(channel)

    # ------------------------------------------------------------ moves

    def _go(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        """GO starts the pending moves, then waits while a move runs or starts ahead of them: MINT is always one
        step ahead (001:3404-3412, 8482)."""
        go = self._access("GO").command
        assert go is not None
        go(channels, arguments)
        clock = self.motion.clock
        waiting = False
        for axis in self.motion.addressed(channels):
            if (axis.move is not None) + axis.triggered >= 2:
                waiting = True
                clock.changes_at(axis.move.end if axis.move is not None else next_profiler_tick(clock.now))
        return waiting

    def _circle(self, name: str) -> Callable[[Channels | None, Values], bool]:
        """CIRCLEA/CIRCLER only on axes 0 and 1 (001:6730)."""
        write = self._access(name).write
        assert write is not None

        def circle(channels: Channels | None, values: Values) -> bool:
            if channels is not None and tuple(channels[:2]) != (0, 1):
                raise MintError(2, channels[0], "circles are on axes 0 and 1 only")
            return write(channels, values)

        return circle

    def _contouring(self, mode: float) -> Callable[[Channels | None, tuple[float, ...]], bool]:
        """CONTON/CONTOFF: contouring for the whole card (001:6995-7033)."""
        write = self._access("CONTOURMODE").write
        assert write is not None
        every = tuple(range(len(self.motion.axes)))
        return lambda channels, arguments: write(every, (mode,) * len(every))

    # ------------------------------------------------------------ errors and recovery

    def motion_error(self, failing: Axis) -> None:
        """A motion error (ABORT included: 001:5591) aborts every other axis and switches the common
        enable off (001:4995-5006)."""
        for axis in self.motion.axes:
            if axis is not failing:
                if not axis.axiserror:
                    axis.latch(ER_ABORT)
                self.motion.crash_group(axis)
            axis.disable()

    def _enable_all(self) -> None:
        """The amplifier enable is one output for every axis (001:7567-7576, 11409-11411)."""
        for axis in self.motion.axes:
            axis.enable()

    def _cancel(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        """CANCEL clears the errors and the move, keeps the position, ends contouring (001:6577-6584)."""
        command = self._access("CANCEL").command
        assert command is not None
        command(channels, arguments)
        self._contouring(0.0)(None, ())
        self._enable_all()
        return False

    def _reset(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        """RESET: CANCEL with POS 0 and the limits on, and outputs, TIME, IMASK and contouring back
        (001:2506, 11409-11444)."""
        command = self._access("RESET").command
        assert command is not None
        command(channels, arguments)
        self._limits(LIMITS_ON)(channels, ())
        self._contouring(0.0)(None, ())
        self._enable_all()
        for reset in self.on_reset:
            reset()
        return False

    def _default(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        """DEFAULT: the axes as at power-up, with v3's power-up values (001:7227-7258)."""
        command = self._access("DEFAULT").command
        assert command is not None
        command(channels, arguments)
        for axis in self.motion.addressed(channels):
            self._power_up(axis)
        return False

    def _zero(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        """ZERO: POS = 0 on the axes (001:12830; v4's replacement, 000:17428)."""
        write = self._access("POS").write
        assert write is not None
        axes = channels if channels is not None else (0,)
        return write(axes, (0.0,) * len(axes))

    def _config(self, channel: int | None, value: float) -> None:
        """CONFIG = _servo or _off: RESET, then the rates back to their defaults (001:6931). Steppers,
        micro-steppers and inverters are not simulated."""
        if value not in (CONFIG_OFF, CONFIG_SERVO):
            raise NotSimulated("CONFIG", "stepper, micro-stepper and inverter axes")
        axis = self.motion.axis(channel)
        self._reset((axis.number,), ())
        for name in RATES:
            axis.parameters[name] = POWER_UP[name]
        axis.parameters["ERRORDECEL"] = POWER_UP["DECEL"]
        self._v4_writer("CONFIG")(channel, value)

    # ------------------------------------------------------------ dedicated inputs

    def _limits(self, mode: float) -> Callable[[Channels | None, tuple[float, ...]], bool]:
        """DISLIMIT switches the limits off and CANCELs (001:7453); ENLIMIT switches them on again."""
        write = self._access("LIMITMODE").write
        assert write is not None

        def command(channels: Channels | None, arguments: tuple[float, ...]) -> bool:
            axes = channels if channels is not None else (0,)
            write(axes, (mode,) * len(axes))
            if mode == LIMITS_OFF:
                self._cancel(channels, arguments)
            return False

        return command

    def _home(self, channels: Channels | None, values: Values) -> bool:
        """HOME, unless the home switch is already open: then "the homing routine will immediately
        terminate" (001:3470)."""
        home = self._access("HOME").write
        switch = self._access("HOMESWITCH").read
        assert home is not None and switch is not None
        axes = channels if channels is not None else (0,)
        closed = [(axis, value) for axis, value in zip(axes, values, strict=False) if not switch(axis)]
        if not closed:
            return False
        return home(tuple(axis for axis, _ in closed), tuple(value for _, value in closed))

    def _stopmode(self, channel: int | None) -> float:
        return self.motion.axis(channel).parameters["STOPINPUTMODE"]

    def _write_stopmode(self, channel: int | None, value: float) -> None:
        if value not in STOPMODES:
            raise MintError(OUT_OF_RANGE, channel, f"STOPMODE = {value:g}")
        self._v4_writer("STOPINPUTMODE")(channel, STOPMODES[value])

    # ------------------------------------------------------------ servo off

    def _servo_on(self, write: Callable[[Channels | None, Values], bool]) -> Callable[[Channels | None, Values], bool]:
        """A move, JOG or TORQUE on an axis SERVOFF holds is "Servo off" (001:13169-13171); TORQUE ends SERVOFF."""

        def checked(channels: Channels | None, values: Values) -> bool:
            for number in channels if channels is not None else (0,):
                if number in self.servo_off and self.motion.axis(number).torque is not None:
                    raise MintError(SERVO_OFF, number, "SERVOFF holds the axis: SERVOC or CANCEL first")
            return write(channels, values)

        return checked

    def _servoff(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        """SERVOFF: the servo loop off, the axis free to move by hand; "TORQUE = 0 ... will produce the same
        effect" (001:11700-11712)."""
        torque = self._v4_write("TORQUE")
        axes = channels if channels is not None else (0,)
        torque(axes, (0.0,) * len(axes))
        self.servo_off.update(axes)
        return False

    def _servoc(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        """SERVOC: the servo on again where the axis is, as STOP after TORQUE = 0 does (001:11629-11662, 11710)."""
        stop = self._access("STOP").command
        assert stop is not None
        axes = tuple(number for number in (channels or (0,)) if self.motion.axis(number).torque is not None)
        self.servo_off.difference_update(axes)
        return stop(axes, arguments) if axes else False

    def _enable(self, _: int | None, value: float) -> None:
        """ENABLE switches the one enable output of every drive (001:7567-7576)."""
        if value not in (0, 1):
            raise MintError(OUT_OF_RANGE, detail=f"ENABLE = {value:g}")
        for axis in self.motion.axes:
            if value:
                axis.enable()
            else:
                self.motion.crash_group(axis)
                axis.disable()
