"""Mint v3 motion keywords: the v4 runtime's axes under their v3 names, with v3's own rules.

* parameters keep their v3 names, power-up values and ranges (``parameters.py``, V3-5);
* writing ACCEL (or ACCELTIME) also writes DECEL unless bit 0 of AXISCON is set
  (001:5662, 5728, 7203); the other AXISCON bits are not simulated;
* SCALE takes whole numbers, rounding a fraction down (001:11610);
* MODE and ERROR read one code, not a bit pattern (001:10038-10061, 4995-5003);
* GO waits while a move runs or starts ahead of the ones it starts (001:3404-3412, V3-10);
* circles are on axes 0 and 1 only (001:6732, 6793);
* SERVOFF is TORQUE = 0, as the guide says (001:11691-11709), with MODE 1 and "Servo off"
  for a move; SERVOC restores the servo where the axis is, as its STOP (001:11629-11662).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from types import MappingProxyType

from mintlang.keyworddb.v3_ranges import AXIS_PARAMETERS
from mintlang.runtime.dialects.v3.handlers import V4Handlers
from mintlang.runtime.dialects.v3.parameters import CHECKED_IN_V3, RENAMED, power_up
from mintlang.runtime.errors import INVALID_AXIS, OUT_OF_RANGE, MintError, NotSimulated
from mintlang.runtime.keywords import Channels, KeywordTable, Values, Writer, per_channel
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
)
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.motion.moves import next_profiler_tick
from mintlang.runtime.ranges import UNBOUNDED

SERVO_OFF = 40  # the v4 error for a drive that is off, which v3 reports as "Servo off"
DECEL_ENABLED = 1  # AXISCON bit 0 (001:6024)
SERVOFF_MODE = 1.0  # _servoff (001:10040)

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

    def __init__(self, motion: Motion, v4: V4Handlers) -> None:
        self.motion = motion
        self.v4 = v4
        self.axiscon = [0] * len(motion.axes)
        self.servo_off: set[int] = set()  # axes SERVOFF put in torque mode (MODE 1 while it lasts)
        for axis in motion.axes:
            axis.bounds.update(dict.fromkeys(CHECKED_IN_V3, UNBOUNDED))  # v3's ranges, not the v4 machine's
            power_up(axis)

    def register(self, table: KeywordTable) -> None:
        v4 = self.v4
        for v3, name in RENAMED.items():
            read = v4.read("IDLE" if v3 == "IDLE" else name)
            table.register(v3, read=read, write=per_channel(self._checked(v3, v4.write_one(name))))
        for name in ("KINT", "KVEL", "KVELFF"):
            table.register(name, read=v4.read(name), write=per_channel(self._checked(name, v4.write_one(name))))
        for name in ("TORQUE", "JOG"):
            write = per_channel(self._checked(name, v4.write_one(name)))
            table.register(name, read=v4.read(name), write=self._servo_on(write))
        for name in ("AXES", "POS", "ENCODER", "STOP", "FASTPOS", "VEL", "ABORT"):
            table.alias(name, v4.access(name))
        table.alias("FOLERR", v4.access("FOLERROR"))
        table.alias("FASTENC", v4.access("FASTENCODER"))
        for name in ("MOVEA", "MOVER"):  # reading one gives the end of the move (001:3186)
            table.register(name, read=v4.read("POSTARGET"), write=self._servo_on(v4.write(name)))
        for name in ("VECTORA", "VECTORR"):
            table.register(name, write=self._servo_on(self._vector(v4.write(name))))
        for name in ("CIRCLEA", "CIRCLER"):
            table.register(name, write=self._servo_on(self._circle(v4.write(name))))
        table.register("SPEED", read=v4.read("SPEED"), write=per_channel(self._checked("SPEED", self._speed)))
        table.register("ACCEL", read=v4.read("ACCEL"), write=per_channel(self._checked("ACCEL", self._accel)))
        table.register("DECEL", read=v4.read("DECEL"), write=per_channel(self._checked("DECEL", self._decel)))
        table.register("ACCELTIME", write=per_channel(self._checked("ACCELTIME", self._acceltime)))
        table.register("AXISCON", read=self._read_axiscon, write=per_channel(self._checked("AXISCON", self._axiscon)))
        table.register("SCALE", read=v4.read("SCALE"), write=per_channel(self._checked("SCALE", self._scale)))
        table.register("RAMP", read=lambda _: 0.0, write=per_channel(self._ramp))
        table.register("MODE", read=self._mode)
        table.register("ERROR", read=self._error)
        table.register("OFFSET", read=self._remaining)
        table.register("GO", command=self._go)
        table.register("ZERO", command=self._zero)
        table.register("SERVOFF", command=self._servoff)
        table.register("SERVOC", command=self._servoc)

    # ---------------------------------------------------------------- values

    def _checked(
        self, name: str, write_one: Callable[[int | None, float], None]
    ) -> Callable[[int | None, float], None]:
        """``write_one`` for values in the v3 range of ``name``, if the tables give one (V3-5)."""
        row = AXIS_PARAMETERS.get(name)
        if row is None:
            return write_one

        def write(channel: int | None, value: float) -> None:
            counts = value * self.motion.axis(channel).scale if row.scaled else value
            if not row.holds(counts):
                raise MintError(OUT_OF_RANGE, channel, f"{name} = {value:g}")
            write_one(channel, value)

        return write

    def _speed(self, channel: int | None, value: float) -> None:
        if value == 0:
            raise NotSimulated("SPEED", "a speed of 0, which v3 accepts: the guide does not say what a move does then")
        self.v4.write_one("SPEED")(channel, value)

    def _accel(self, channel: int | None, value: float) -> None:
        """ACCEL, and DECEL with it unless AXISCON bit 0 is set (001:5662)."""
        self.v4.write_one("ACCEL")(channel, value)
        self._follow_accel(channel)

    def _acceltime(self, channel: int | None, value: float) -> None:
        """ACCELTIME writes ACCEL, so DECEL follows as for ACCEL (001:5728), at rates above the range ACCEL and
        DECEL take if need be (001:5680, 5726)."""
        self.v4.write_one("ACCELTIME")(channel, value)
        axis = self.motion.axis(channel)
        if not self.axiscon[axis.number] & DECEL_ENABLED:
            self.v4.write_one("DECELTIME")(channel, value)
            axis.parameters["ERRORDECEL"] = axis.parameters["DECEL"]  # the stop input's rate (001:7219)

    def _follow_accel(self, channel: int | None) -> None:
        axis = self.motion.axis(channel)
        if not self.axiscon[axis.number] & DECEL_ENABLED:
            self._decel(channel, axis.get("ACCEL"))

    def _decel(self, channel: int | None, value: float) -> None:
        """DECEL, which the stop input ramps down at too (001:7219)."""
        self.v4.write_one("DECEL")(channel, value)
        self.v4.write_one("ERRORDECEL")(channel, value)

    def _read_axiscon(self, channel: int | None) -> float:
        return float(self.axiscon[self.motion.axis(channel).number])

    def _axiscon(self, channel: int | None, value: float) -> None:
        axis = self.motion.axis(channel)
        if int(value) & ~DECEL_ENABLED:
            raise NotSimulated("AXISCON", "bits 1 to 7 (the encoder board, following error off, MOVER's target)")
        self.axiscon[axis.number] = int(value)

    def _scale(self, channel: int | None, value: float) -> None:
        """SCALE takes whole numbers: a fraction is rounded down (001:11610)."""
        self.v4.write_one("SCALE")(channel, float(math.floor(value)))

    @staticmethod
    def _ramp(channel: int | None, value: float) -> None:
        """RAMP 0 is the trapezoid; the guide does not give the shape of the others (001:11212-11236)."""
        if value != 0:
            raise NotSimulated("RAMP", "an S-ramp (RAMP other than 0)")

    # ---------------------------------------------------------------- reading

    def _mode(self, channel: int | None) -> float:
        axis = self.motion.axis(channel)
        if axis.number in self.servo_off and axis.torque is not None:
            return SERVOFF_MODE
        bits = int(self.v4.read("AXISMODE")(channel))
        if bits not in _MODES:
            raise NotSimulated("MODE", f"the v4 motion modes {bits}, which have no v3 code")
        return _MODES[bits]

    def _error(self, channel: int | None) -> float:
        bits = int(self.v4.read("AXISERROR")(channel))
        return next((code for mask, code in _ERRORS if bits & mask), 0.0)

    def _remaining(self, channel: int | None) -> float:
        """Reading OFFSET gives the rest of the move, always positive (001:3226-3241)."""
        return abs(self.v4.read("POSREMAINING")(channel))

    # ---------------------------------------------------------------- moves

    def _go(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        """GO starts the pending moves, then waits while a move runs or starts ahead of them: MINT is always one
        step ahead (001:3404-3412, 8482). An axis in torque mode (TORQUE, SERVOFF) is left out, where v4's GO is
        error 10: v3's GO page names that error for a JOG only (001:8472-8504)."""
        servoing = tuple(axis.number for axis in self.motion.addressed(channels) if axis.torque is None)
        self.v4.command("GO")(servoing, arguments)
        clock = self.motion.clock
        waiting = False
        for axis in self.motion.addressed(channels):
            if (axis.move is not None) + axis.triggered >= 2:
                waiting = True
                clock.changes_at(axis.move.end if axis.move is not None else next_profiler_tick(clock.now))
        return waiting

    @staticmethod
    def _vector(write: Writer) -> Writer:
        """VECTORA/VECTORR on at least two axes (001:3257); on one, "Invalid axis" (``VR[0] = 100``,
        001:13173-13183)."""

        def vector(channels: Channels | None, values: Values) -> bool:
            if channels is None or len(channels) < 2 or len(values) < 2:  # VR = 5 moves one axis too
                axis = channels[0] if channels else None
                raise MintError(INVALID_AXIS, axis, "a vector move needs at least two axes")
            return write(channels, values)

        return vector

    @staticmethod
    def _circle(write: Writer) -> Writer:
        """CIRCLEA/CIRCLER only on axes 0 and 1 (001:6732, 6793)."""

        def circle(channels: Channels | None, values: Values) -> bool:
            if channels is not None and tuple(channels[:2]) != (0, 1):
                raise MintError(INVALID_AXIS, channels[0], "circles are on axes 0 and 1 only")
            return write(channels, values)

        return circle

    def _zero(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        """ZERO: POS = 0 on the axes (001:12830; v4's replacement, 000:17428)."""
        axes = channels if channels is not None else (0,)
        return self.v4.write("POS")(axes, (0.0,) * len(axes))

    # ---------------------------------------------------------------- servo off

    def _servo_on(self, write: Writer) -> Writer:
        """A move, JOG or TORQUE on an axis SERVOFF holds is "Servo off" (001:13169-13171)."""

        def checked(channels: Channels | None, values: Values) -> bool:
            for number in channels if channels is not None else (0,):
                if number in self.servo_off and self.motion.axis(number).torque is not None:
                    raise MintError(SERVO_OFF, number, "SERVOFF holds the axis: SERVOC or CANCEL first")
            return write(channels, values)

        return checked

    def _servoff(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        """SERVOFF: the servo loop off, the axis free to move by hand; "TORQUE = 0 ... will produce the same
        effect" (001:11691-11709)."""
        axes = channels if channels is not None else (0,)
        self.v4.write("TORQUE")(axes, (0.0,) * len(axes))
        self.servo_off.update(axes)
        return False

    def _servoc(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        """SERVOC: the servo on again where the axis is, as STOP after TORQUE = 0 does (001:11629-11662,
        11702-11709)."""
        axes = tuple(number for number in (channels or (0,)) if self.motion.axis(number).torque is not None)
        self.servo_off.difference_update(axes)
        return self.v4.command("STOP")(axes, arguments) if axes else False
