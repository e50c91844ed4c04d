"""What an axis's encoder reads back each servo tick: the simulated motor and load (spec W-1).

The manual describes controllers, not machines, so every model here is a
runtime choice. Each servo tick the runtime first advances the plant, which
answers the encoder count at that tick, and then runs the servo law on it:

    measured = plant.step(demand, dac, dt)  # dac: the command computed at the previous tick
    dac = loop.step(demand, velocity, acceleration, measured, measured - previous)

so the DAC is a zero-order hold over the tick that follows its computation.
Only plants with ``closed_loop`` respond to the DAC. The runtime runs the law
on every plant but the ideal one, so a stalled axis's DAC still shows the
controller pushing against its following error.
``demand`` is the tick's demand position, or None while nothing servoes the
axis (drive disabled, open-loop ``TORQUE``). Positions are physical counts
since power-up; ``POS`` offsets belong to the runtime.
"""

from __future__ import annotations

import math
from typing import ClassVar, Protocol

from mintlang.runtime.motion.servo import ServoGains


def round_half_away(value: float) -> int:
    """Nearest integer, halves away from zero: the encoder count of a demand (spec W-1).

    Python's ``round`` rounds halves to even, which would make +0.5 and +1.5
    counts of demand land asymmetrically.
    """
    if value >= 0.0:
        whole = int(value)  # exact: the fraction left, value - whole, is representable
        return whole + 1 if value - whole >= 0.5 else whole
    whole = int(-value)
    return -(whole + 1) if -value - whole >= 0.5 else -whole


class Plant(Protocol):
    """A per-axis model of motor, load and encoder.

    ``closed_loop`` tells the runtime whether the DAC moves anything, that is
    whether the plant has to be integrated every tick for the axis to follow
    its demand.
    """

    closed_loop: ClassVar[bool]

    def step(self, demand: float | None, dac: float, dt: float) -> int:
        """Advance the model by ``dt`` seconds, ``dac`` percent held throughout, and return the encoder count now."""
        ...


class IdealPlant:
    """The default: the axis is exactly where it is told to be, to the nearest count, whatever the gains."""

    closed_loop: ClassVar[bool] = False
    __slots__ = ("position",)

    def __init__(self, position: int = 0) -> None:
        self.position = position

    def step(self, demand: float | None, dac: float, dt: float) -> int:
        """Follow the demand; hold while nothing is servoing the axis."""
        if demand is not None:
            self.position = round_half_away(demand)
        return self.position


class StalledPlant:
    """A jammed axis, or what the manual's all-zero default gains do to a real one: the encoder never changes."""

    closed_loop: ClassVar[bool] = False
    __slots__ = ("position",)

    def __init__(self, position: int = 0) -> None:
        self.position = position

    def step(self, demand: float | None, dac: float, dt: float) -> int:
        """Ignore everything."""
        return self.position


class VelocityPlant:
    """A velocity amplifier (``velamp k``): the motor turns at ``k`` counts/s per percent of DAC, instantly."""

    closed_loop: ClassVar[bool] = True
    __slots__ = ("_position", "counts_per_second")

    def __init__(self, counts_per_second: float, position: float = 0.0) -> None:
        self.counts_per_second = counts_per_second
        self._position = position

    def step(self, demand: float | None, dac: float, dt: float) -> int:
        """Integrate the commanded speed; exact, since the DAC holds its value through the tick."""
        self._position += self.counts_per_second * dac * dt
        return round_half_away(self._position)


class TorquePlant:
    """A torque (current) amplifier driving an inertia with viscous and Coulomb friction.

    The acceleration is ``gain·DAC - viscous·v - coulomb·sign(v)``. The
    defaults picture a 4000 counts/rev encoder on a motor and load that reach
    5·10⁶ counts/s² at full DAC, coast to rest with a 0.1 s time constant
    (so 100 % DAC alone would settle at 500 000 counts/s, 7500 rpm) and need
    0.4 % DAC to break away.

    The DAC is constant through a tick, so between friction sign changes the
    motion is a first-order linear system integrated exactly: unconditionally
    stable at any tick length. When friction would reverse the motion inside a
    tick, the motor stops there and stays stopped until the next tick.
    """

    closed_loop: ClassVar[bool] = True
    __slots__ = ("_decay", "_dt", "_position", "_spread", "coulomb", "gain", "velocity", "viscous")

    def __init__(self, gain: float = 50_000.0, viscous: float = 10.0, coulomb: float = 20_000.0) -> None:
        """``gain`` in counts/s² per percent of DAC, ``viscous`` in 1/s (> 0), ``coulomb`` in counts/s²."""
        if not viscous > 0.0:
            raise ValueError(f"viscous friction must be positive, not {viscous}")
        self.gain = gain
        self.viscous = viscous
        self.coulomb = coulomb
        self.velocity = 0.0
        self._position = 0.0
        self._dt = 0.0
        self._decay = 1.0
        self._spread = 0.0

    @property
    def position(self) -> float:
        """The true (unquantised) position in counts."""
        return self._position

    def step(self, demand: float | None, dac: float, dt: float) -> int:
        """Integrate one tick of the motion under a constant DAC command and read the encoder."""
        if dt != self._dt:
            # v(t) = v∞ + (v0 - v∞)·decay; x(t) = x0 + v∞·t + (v0 - v∞)·spread.
            self._dt = dt
            self._decay = math.exp(-self.viscous * dt)
            self._spread = -math.expm1(-self.viscous * dt) / self.viscous
        velocity = self.velocity
        drive = self.gain * dac
        if velocity == 0.0:
            if abs(drive) <= self.coulomb:
                return round_half_away(self._position)
            force = drive - math.copysign(self.coulomb, drive)
        else:
            force = drive - math.copysign(self.coulomb, velocity)
        terminal = force / self.viscous
        moved = velocity - terminal
        new_velocity = terminal + moved * self._decay
        if new_velocity * velocity < 0.0:
            # Friction won: the motor halts when v∞ + (v0 - v∞)·e^(-bt) reaches 0, after covering v0/b - v∞·t.
            stop_time = math.log(moved / -terminal) / self.viscous
            self._position += velocity / self.viscous + terminal * stop_time
            self.velocity = 0.0
        else:
            self._position += terminal * dt + moved * self._spread
            self.velocity = new_velocity
        return round_half_away(self._position)


TORQUE_PLANT_GAINS = ServoGains(kprop=0.5, kderiv=6.0, kvelff=0.2, kaccel=20.0)
"""Gains that make the default ``TorquePlant`` follow a default-parameter move within a few counts.

Found by a one-off grid search over simulated 4000- and 137-count moves at
SPEED 20000, ACCEL = DECEL 300000. KP and KD place the loop near 25 Hz with
damping close to critical; KVELFF cancels the viscous drag
(10/s ÷ 50000 counts/s²/% · 1000 samples/s) and KACCEL the inertia
(1/50000 · 10⁶ samples²/s²), so the error stays within ±2 counts.
"""
