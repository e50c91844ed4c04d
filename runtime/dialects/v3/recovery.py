"""Mint v3 motion errors and recovering from them: one error stops every axis; CANCEL, RESET and DISLIMIT recover.

* A motion error on one axis aborts the others (``ERROR`` 1 there) and switches the
  common amplifier enable off (001:4995-5006, 5591, 7567) (V3-6).
* ``CANCEL`` clears the errors and the moves, keeps the positions and ends contouring
  (001:6577-6584), but not a limit error whose switch is still open while the limits are
  watched (001:6582: ``DISLIMIT`` clears that one); ``RESET`` also zeroes the positions
  and the encoders, watches the limits again and clears the outputs, ``TIME`` and
  ``IMASK`` (001:2506, 11409-11444); ``DISLIMIT`` ignores
  the limits and cancels, ``ENLIMIT`` watches them again (001:7433-7470). Each switches
  the enable on again, so a handler can ``CANCEL : RETURN`` and move on (001:5037-5066), though
  ``CANCEL`` and ``DISLIMIT`` not before ``RESET``, ``CONFIG`` or ``ENABLE = 1`` did (001:11409-11411).
* ``CONFIG = _servo`` or ``_off`` issues a ``RESET`` and restores the rates (001:6931-6939);
  ``DEFAULT`` restores every v3 power-up value and resets what ``RESET`` does (001:7227-7258); ``ENABLE`` switches the
  enable (001:7547-7576); ``CONTON``/``CONTOFF`` contour on the whole card (001:6995-7033).
"""

from __future__ import annotations

from collections.abc import Callable

from mintlang.runtime.dialects.v3.handlers import V4Handlers
from mintlang.runtime.dialects.v3.parameters import POWER_UP, power_up
from mintlang.runtime.errors import NotSimulated
from mintlang.runtime.keywords import Channels, Command, KeywordTable, per_channel
from mintlang.runtime.motion.axis import ER_ABORT, ER_FWD_HARD, ER_REV_HARD, Axis
from mintlang.runtime.motion.commands import Motion

LIMITS_WATCHED, LIMITS_IGNORED = 1.0, 0.0  # LIMITMODE: crash stop (and the v3 abort), or ignore
LIMIT_ERRORS = ER_FWD_HARD | ER_REV_HARD
CONFIG_OFF, CONFIG_SERVO = 0, 1
RATES = ("SPEED", "ACCEL", "DECEL", "ERRORDECEL", "HOMESPEED")  # what CONFIG restores (001:6931)
_AMPLIFIERS_OFF = (  # they power up so (001:11409-11411), and a motion error or ENABLE = 0 switches them off
    "the amplifiers are disabled until RESET, CONFIG or ENABLE = 1 enables them, or run with --drives enabled"
)


class V3Recovery:
    """What a motion error does to every axis, and the keywords that clear it."""

    def __init__(self, motion: Motion, v4: V4Handlers) -> None:
        self.motion = motion
        self.v4 = v4
        self.on_reset: list[Callable[[], None]] = []  # what RESET clears besides the axes (outputs, TIME, IMASK)
        # whether the enable was switched on since power-up, before which CANCEL leaves it off (001:11409-11411);
        # drives enabled when the run starts stand for a configuration that did
        self.switched_on = any(axis.enabled for axis in motion.axes)
        for axis in motion.axes:  # error 40's hint in v3's words: v3 has no DRIVEENABLE
            axis.disabled_hint = _AMPLIFIERS_OFF

    def register(self, table: KeywordTable) -> None:
        table.register("CANCEL", command=self._cancel)
        table.register("RESET", command=self._reset)
        table.register("DISLIMIT", command=self._limits(LIMITS_IGNORED))
        table.register("ENLIMIT", command=self._limits(LIMITS_WATCHED))
        table.register("DEFAULT", command=self._default)
        table.register("CONFIG", read=self.v4.read("CONFIG"), write=per_channel(self._config))
        table.register("ENABLE", write=per_channel(self._enable))
        table.register("CONTON", command=self._contouring(1.0))
        table.register("CONTOFF", command=self._contouring(0.0))

    def motion_error(self, failing: Axis) -> None:
        """After the failing axis's own default action: every other axis aborted, the enable off."""
        for axis in self.motion.axes:
            if axis is not failing:
                if not axis.axiserror:
                    axis.latch(ER_ABORT)
                self.motion.crash_group(axis)
            axis.disable()

    def _recovered(self) -> None:
        """Contouring off, and the amplifier enable, one output for every axis, on (001:6584, 7567-7576), unless it
        has been off since power-up: only RESET, CONFIG or ENABLE = 1 switches it on then (001:11409-11411)."""
        self._contouring(0.0)(None, ())
        if self.switched_on:
            for axis in self.motion.axes:
                axis.enable()

    def _cancel(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        kept = [axis for axis in self.motion.addressed(channels) if self._on_its_limit(axis)]
        self.v4.command("CANCEL")(channels, arguments)
        for axis in kept:  # one switch for both directions (V3-8): an axis at rest on it would trip the other one
            axis.axiserror |= LIMIT_ERRORS
        self._recovered()
        return False

    def _on_its_limit(self, axis: Axis) -> bool:
        """A limit error whose switch is still open and watched, which CANCEL does not clear (001:6582)."""
        p = axis.parameters
        switches = (int(p["LIMITFORWARDINPUT"]), int(p["LIMITREVERSEINPUT"]))
        return (
            bool(axis.axiserror & LIMIT_ERRORS)
            and p["LIMITMODE"] != LIMITS_IGNORED
            and any(channel >= 0 and self.motion.input_active(channel) for channel in switches)
        )

    def _reset(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        self.switched_on = True
        self.v4.command("RESET")(channels, arguments)
        for axis in self.motion.addressed(channels):  # v3's RESET zeroes ENCODER with POS (001:11433, 11441)
            axis.encoder_offset = float(axis.measured)
        self._limits(LIMITS_WATCHED)(channels, ())
        self._recovered()
        for reset in self.on_reset:
            reset()
        return False

    def _limits(self, mode: float) -> Command:
        write = self.v4.write("LIMITMODE")

        def command(channels: Channels | None, arguments: tuple[float, ...]) -> bool:
            axes = channels if channels is not None else (0,)
            write(axes, (mode,) * len(axes))
            if mode == LIMITS_IGNORED:
                self._cancel(channels, arguments)
            return False

        return command

    def _default(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        """The power-up values, and what RESET resets besides the axes: the guide tells DEFAULT from RESET only
        by the parameters RESET leaves (001:7244-7251). The enable is left as it is (001:7244 against 11411)."""
        self.v4.command("DEFAULT")(channels, arguments)  # the move, the errors, POS, ENCODER, the limits watched
        for axis in self.motion.addressed(channels):
            power_up(axis)
        self._contouring(0.0)(None, ())
        for reset in self.on_reset:
            reset()
        return False

    def _config(self, channel: int | None, value: float) -> None:
        """CONFIG = _servo or _off; steppers, micro-steppers and inverters are not simulated."""
        if value not in (CONFIG_OFF, CONFIG_SERVO):
            raise NotSimulated("CONFIG", "stepper, micro-stepper and inverter axes")
        axis = self.motion.axis(channel)
        self._reset((axis.number,), ())
        for name in RATES:
            axis.parameters[name] = POWER_UP[name]  # in counts, whatever SCALE is
        axis.set("CONFIG", value)  # not v4's CONFIG, which calls DEFAULT (000:8481-8483): v3 restores only the rates

    def _enable(self, _: int | None, value: float) -> None:
        """0 or 1, as the table holds it (``v3_ranges``)."""
        self.switched_on = self.switched_on or bool(value)
        for axis in self.motion.axes:
            if value:
                axis.enable()
            else:
                self.motion.crash_group(axis)
                axis.disable()

    def _contouring(self, mode: float) -> Command:
        write = self.v4.write("CONTOURMODE")
        every = tuple(range(len(self.motion.axes)))
        return lambda channels, arguments: write(every, (mode,) * len(every))
