"""The stop input of each axis (``STOPINPUT``, ``STOPINPUTMODE``; spec AX-17, AX-18, EV-8).

An active stop input is not an error: ``AXISSTATUS`` shows it and ``#STOP``
is called once per activation, immediately (mode 0 ignore, mode 2 cancel) or
once the axis has ramped to rest at ``ERRORDECEL`` (mode 1 normal, mode 3
stop). Mode 1 holds the move instead of clearing it: when the input clears the
axis ramps back up at ``ACCEL`` and finishes the move, and ``#STOP`` is not
called if that happens before it came to rest. Moves that do not run on the
trapezoid profiler (homing, following, cams, torque, blended paths) are not
ramped: there mode 1 acts as mode 0 and modes 2 and 3 crash-stop. On a Mint v3
controller ``#STOP`` comes on the input's rising edge whatever the mode (001:2510).
"""

from __future__ import annotations

from collections.abc import Callable

from mintlang.runtime.motion.axis import Axis
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.motion.holding import Held, hold, release
from mintlang.runtime.motion.moves import PlannedMove, next_profiler_tick

IGNORE, NORMAL, CANCEL, STOP = 0, 1, 2, 3


class StopInputs:
    def __init__(self, motion: Motion, raise_stop: Callable[[], None], *, at_edge: bool = False) -> None:
        """``at_edge``: ``#STOP`` is called when the input becomes active, not when the axis is at rest."""
        self.motion = motion
        self.raise_stop = raise_stop  # make #STOP pending (when the program has the handler)
        self.at_edge = at_edge
        self.active: set[int] = set()  # axes whose stop input is active
        self.await_rest: set[int] = set()  # axes that call #STOP when they come to rest
        self.held: dict[int, Held] = {}  # mode 1: the move and its stop ramp

    def update(self, axis: Axis, active: bool, tick: int) -> None:
        number = axis.number
        if active and number not in self.active:
            self.active.add(number)
            self._activated(axis, tick)
        elif not active and number in self.active:
            self.active.discard(number)
            self._cleared(axis)
        move = axis.move
        if number in self.await_rest and (move is None or (axis.held and tick >= move.end)):
            self.await_rest.discard(number)
            self.raise_stop()

    def _activated(self, axis: Axis, tick: int) -> None:
        mode = int(axis.parameters["STOPINPUTMODE"])
        move = axis.move
        ramped = type(move) is PlannedMove and axis.torque is None
        decel = self.motion.error_decel(axis)
        if mode == IGNORE or (mode == NORMAL and not ramped):
            self.raise_stop()
        elif mode == CANCEL or not ramped or decel == 0.0:  # no rate to ramp down at
            self.motion.crash_group(axis)
            self.raise_stop()
        else:
            if mode == STOP:
                self.motion.stop_group(axis, next_profiler_tick(tick), decel)
            else:
                self._hold(axis, move, next_profiler_tick(tick), decel)  # type: ignore[arg-type]
            if self.at_edge:
                self.raise_stop()
            else:
                self.await_rest.add(axis.number)

    def _hold(self, axis: Axis, move: PlannedMove, tick: int, decel: float) -> None:
        """Ramp the move down at ``decel`` (ERRORDECEL) but keep it, and what is buffered behind it, to resume.

        The ramp does not complete while the axis is held, so AXISMODE keeps showing the move and
        IDLE stays 0: the program waiting for the move waits for the input to clear.
        """
        self.held[axis.number] = hold(self.motion, move, tick, decel)

    def _cleared(self, axis: Axis) -> None:
        held = self.held.pop(axis.number, None)
        if held is None:
            return
        self.await_rest.discard(axis.number)
        release(self.motion, held)
