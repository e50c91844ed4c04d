"""Asynchronous motion errors: detection every servo tick and the default actions (spec §4).

A condition first shows in ``AXISSTATUS``; unless its mode is "ignore" it is
latched in ``AXISERROR``, the mode's default action runs at once and
``#ONERROR`` becomes pending. The modes share one table (``LIMITMODE``'s, as
the spec recommends for the Advanced-only ones): 0 ignore, 1 crash stop and
disable, 2 crash stop, 3 ramp down at ``ERRORDECEL`` (a crash stop when idle or
in torque, follow, fly or cam mode), 5 only call the handler.
``SOFTLIMITMODE`` 4 stops a move on the limit before it is passed
(``smart_limits.py``); what it cannot stop so is crash-stopped.
"""

from __future__ import annotations

from collections.abc import Callable

from mintlang.runtime.motion.axis import (
    ER_ERROR_INPUT,
    ER_FOLLOWING,
    ER_FWD_HARD,
    ER_FWD_SOFT,
    ER_REV_HARD,
    ER_REV_SOFT,
    ER_STOP_INPUT,
    MD_CAM,
    MD_FLY,
    MD_FOLLOW,
    MD_TORQUE,
    NOISE,
    Axis,
    wrap,
)
from mintlang.runtime.motion.commands import SMART_SOFT_LIMITS, Motion
from mintlang.runtime.motion.moves import next_profiler_tick
from mintlang.runtime.motion.smart_limits import SmartLimits
from mintlang.runtime.motion.stop_input import StopInputs

IGNORE, CRASH_STOP_DISABLE, CRASH_STOP, ERROR_DECEL, CALL_HANDLER = 0, 1, 2, 3, 5
MODE_OF_ERROR = {
    ER_FOLLOWING: "FOLERRORMODE",
    ER_FWD_HARD: "LIMITMODE",
    ER_REV_HARD: "LIMITMODE",
    ER_FWD_SOFT: "SOFTLIMITMODE",
    ER_REV_SOFT: "SOFTLIMITMODE",
    ER_ERROR_INPUT: "ERRORINPUTMODE",
}
# in these modes an error in mode 3 crash-stops the axis, as mode 2, instead of ramping (000:13515-13517, 16091-16093)
NOT_RAMPED = MD_TORQUE | MD_FOLLOW | MD_FLY | MD_CAM


class Supervisor:
    """Checks each enabled axis once per servo tick and applies the default actions."""

    def __init__(self, motion: Motion, raise_error: Callable[[Axis], None], stop_inputs: StopInputs) -> None:
        self.motion = motion
        self.is_active = motion.input_active  # digital input channel -> active now
        self.raise_error = raise_error  # #ONERROR pending (or the end of the run without a handler)
        self.stop_inputs = stop_inputs
        self.stopping: list[Axis] = []  # ramping down at ERRORDECEL: #ONERROR waits until they are at rest
        self.smart = SmartLimits(motion, raise_error)
        motion.soft_limits_changed = self.smart.limits_changed

    def at_rest(self) -> None:
        """Make #ONERROR pending for error ramps that have ended (mode 3 calls it at rest, AX-13, AX-15)."""
        for axis in [axis for axis in self.stopping if axis.move is None]:
            self.stopping.remove(axis)
            if axis.axiserror:
                self.raise_error(axis)

    def check(self, axis: Axis, tick: int) -> None:
        p = axis.parameters
        following = axis.enabled and abs(axis.demand - axis.measured) - NOISE > p["FOLERRORFATAL"]
        if not axis.guarded:  # no limit, error or stop input and default software limits: the common case
            axis.status = ER_FOLLOWING if following else 0
            if following and not axis.axiserror & ER_FOLLOWING:
                self.error(axis, ER_FOLLOWING, tick)
            return
        status = ER_FOLLOWING if following else 0
        smart = self.smart.check(axis, tick)
        forward = int(p["LIMITFORWARDINPUT"])
        reverse = int(p["LIMITREVERSEINPUT"])
        position = wrap(axis.demand - axis.position_offset)
        forward_soft = position - NOISE > p["SOFTLIMITFORWARD"]
        reverse_soft = position + NOISE < p["SOFTLIMITREVERSE"]
        if forward >= 0 or reverse >= 0 or forward_soft or reverse_soft:
            velocity = axis.velocity_demand(tick)
            if forward >= 0 and self.is_active(forward) and velocity >= 0:
                status |= ER_FWD_HARD
            if reverse >= 0 and self.is_active(reverse) and velocity <= 0:
                status |= ER_REV_HARD
            if forward_soft and velocity > 0:
                status |= ER_FWD_SOFT
            if reverse_soft and velocity < 0:
                status |= ER_REV_SOFT
        error_input = int(p["ERRORINPUT"])
        if error_input >= 0 and self.is_active(error_input):
            status |= ER_ERROR_INPUT
        stop_input = int(p["STOPINPUT"])
        if stop_input >= 0:
            active = self.is_active(stop_input)
            if active:
                status |= ER_STOP_INPUT
            self.stop_inputs.update(axis, active, tick)
        axis.status = status
        fresh = status & ~axis.axiserror & ~ER_STOP_INPUT & ~(ER_FWD_SOFT | ER_REV_SOFT if smart else 0)
        if not fresh or not axis.enabled:  # a disabled axis shows its switches but latches nothing
            return
        bit = 1
        while fresh:
            if fresh & 1:
                self.error(axis, bit, tick)
            fresh >>= 1
            bit <<= 1

    def error(self, axis: Axis, bit: int, tick: int) -> None:
        """Latch ``bit`` unless its mode ignores it, run the default action, make #ONERROR pending."""
        mode = int(axis.parameters[MODE_OF_ERROR[bit]]) if bit in MODE_OF_ERROR else CRASH_STOP_DISABLE
        if mode == IGNORE:
            return
        axis.latch(bit)
        ramped = mode == ERROR_DECEL and axis.move is not None and not axis.axismode & NOT_RAMPED
        if mode in (CRASH_STOP_DISABLE, CRASH_STOP, SMART_SOFT_LIMITS) or (mode == ERROR_DECEL and not ramped):
            self.motion.crash_group(axis)
            if mode == CRASH_STOP_DISABLE:
                axis.disable()
        elif ramped:
            self.motion.stop_group(axis, next_profiler_tick(tick), self.motion.error_decel(axis))
            if axis.move is not None:
                if axis not in self.stopping:
                    self.stopping.append(axis)
                return
        if axis in self.stopping:
            self.stopping.remove(axis)
        self.raise_error(axis)
