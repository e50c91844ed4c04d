"""One-dimensional motion planning in counts and seconds: trapezoids, triangles, S-ramps and jogs.

The profiler knows nothing about Mint, axes or ticks: the runtime converts user
units to counts, plans a ``Profile`` when a move starts (or re-plans from the
current position and velocity when ``SPEED``/``ACCEL``/``DECEL`` change,
spec MP-10) and samples it every profiler tick.

Every plan is a closed form, as in ODrive's ``planTrapezoidal``: a ramp from
``v0`` to ``v1`` at rate ``a`` covers ``(v1² - v0²)/(2a)``, so the phase times
follow without iteration and the move's duration is exact, which the tests
use as their oracle.

SRAMP (spec MP-9) keeps ``ACCEL``/``DECEL`` as the *peak* acceleration: a
fraction ``SRAMP/100`` of every ramp's time is spent changing acceleration at
constant jerk, half at the start of the ramp and half at its end. Such a ramp
takes as long, and covers as much distance, as a constant-acceleration ramp
at ``rate·(1 - SRAMP/200)``; an S-ramped move is therefore the trapezoid
planned at those reduced rates with each ramp reshaped in place, which keeps
the closed form, ends on the target and is always longer than the trapezoid.
"""

from __future__ import annotations

import math
from bisect import bisect_right
from collections.abc import Iterable
from dataclasses import field

from mintlang.records import record

# (t0, x0, v0, a0/2, j/6, a0, j/2): a cubic in τ = t - t0 and its derivative, pre-scaled for Horner evaluation.
_Segment = tuple[float, float, float, float, float, float, float]
# (duration, velocity at start, velocity at end) of a constant-acceleration phase.
_Phase = tuple[float, float, float]


@record
class Profile:
    """A planned motion from position 0, sampled by time since its start.

    ``duration`` is when the last ramp ends. From then on the motion continues
    at ``final_velocity`` from ``distance``: a positional move rests exactly on
    its target (``final_velocity`` 0), a jog keeps its speed for ever.
    """

    duration: float
    distance: float
    final_velocity: float = 0.0
    _boundaries: tuple[float, ...] = field(default=(), repr=False)
    _segments: tuple[_Segment, ...] = field(default=(), repr=False)

    def sample(self, t: float) -> tuple[float, float]:
        """(position, velocity) at ``t ≥ 0`` seconds; exactly ``(distance, 0.0)`` once a positional move is over."""
        if t >= self.duration:
            return self.distance + self.final_velocity * (t - self.duration), self.final_velocity
        t0, x0, v0, a_half, j_sixth, a0, j_half = self._segments[bisect_right(self._boundaries, t)]
        tau = t - t0
        return x0 + tau * (v0 + tau * (a_half + tau * j_sixth)), v0 + tau * (a0 + tau * j_half)


def stopping_distance(velocity: float, decel: float) -> float:
    """Signed displacement needed to come to rest from ``velocity`` at ``decel`` (same sign as the velocity)."""
    return velocity * abs(velocity) / (2.0 * decel)


def plan_move(
    distance: float,
    speed: float,
    accel: float,
    decel: float,
    start_velocity: float = 0.0,
    *,
    sramp: float = 0.0,
) -> Profile:
    """Plan a positional move of ``distance`` counts that ends at rest exactly on its target.

    Starting with velocity away from the target (or sitting on it while
    moving), the axis first stops at ``decel`` and then comes back. Starting
    faster than ``speed``, it slows to ``speed`` at ``decel``. Starting toward
    the target too close to stop at ``decel``, it stops at the raised rate
    ``v²/(2·remaining)`` so the target is never overshot (spec MP-10 RC).
    ``sramp`` (0-100) S-shapes every ramp as the module describes, keeping
    ``accel`` and ``decel`` as peak rates.
    """
    _check_positive(speed=speed, accel=accel, decel=decel)
    if not 0.0 <= sramp <= 100.0:
        raise ValueError(f"sramp must lie in 0..100, not {sramp}")
    smooth = sramp / 100.0
    accel *= 1.0 - smooth / 2.0
    decel *= 1.0 - smooth / 2.0
    # Work toward +; a move of 0 with a moving start is "behind" the axis, so it stops and returns.
    direction = 1.0 if distance > 0.0 or (distance == 0.0 and start_velocity < 0.0) else -1.0
    remaining = abs(distance)
    v = start_velocity * direction
    phases: list[_Phase] = []
    if v < 0.0:
        phases.append((-v / decel, v, 0.0))
        remaining += v * v / (2.0 * decel)
        v = 0.0
    if v * v >= 2.0 * decel * remaining:
        if v > 0.0:
            phases.append((2.0 * remaining / v, v, 0.0))
    elif v >= speed:
        cruise = remaining - v * v / (2.0 * decel)
        phases += [((v - speed) / decel, v, speed), (cruise / speed, speed, speed), (speed / decel, speed, 0.0)]
    else:
        ramps = (speed - v) * (speed + v) / (2.0 * accel) + speed * speed / (2.0 * decel)
        if remaining >= ramps:
            phases += [((speed - v) / accel, v, speed), ((remaining - ramps) / speed, speed, speed)]
            peak = speed
        else:
            peak = math.sqrt((2.0 * accel * decel * remaining + decel * v * v) / (accel + decel))
            # (peak - v)/accel without subtracting two nearly equal speeds, which a slow accel would magnify.
            phases.append(((2.0 * decel * remaining - v * v) / ((accel + decel) * (peak + v)), v, peak))
        phases.append((peak / decel, peak, 0.0))
    return _build(((t, v0 * direction, v1 * direction) for t, v0, v1 in phases), smooth, distance, 0.0)


def plan_velocity(start_velocity: float, target_velocity: float, accel: float, decel: float) -> Profile:
    """Plan a ramp to a constant velocity (JOG, spec MP-16); SRAMP never applies.

    Speeding up uses ``accel`` and slowing down ``decel``; a reversal slows to
    rest at ``decel`` and then speeds up at ``accel``. The profile is
    unbounded: after ``duration`` it keeps ``target_velocity``.
    """
    _check_positive(accel=accel, decel=decel)
    phases: list[_Phase] = []
    v = start_velocity
    if v * target_velocity < 0.0:
        phases.append((abs(v) / decel, v, 0.0))
        v = 0.0
    if target_velocity != v:
        rate = accel if abs(target_velocity) > abs(v) else decel
        phases.append((abs(target_velocity - v) / rate, v, target_velocity))
    return _build(phases, 0.0, None, target_velocity)


def _check_positive(**rates: float) -> None:
    """Reject rates the closed forms divide by; the interpreter range-checks them long before (spec MP-2, MP-3)."""
    for name, value in rates.items():
        if not value > 0.0:
            raise ValueError(f"{name} must be positive, not {value}")


def _build(phases: Iterable[_Phase], smooth: float, distance: float | None, final_velocity: float) -> Profile:
    """Chain constant-acceleration phases into sampled segments, S-shaping each ramp when ``smooth`` > 0.

    ``distance`` None means the end position is whatever the phases cover (a jog ramp).
    """
    segments: list[_Segment] = []
    t = x = 0.0
    for duration, v0, v1 in phases:
        if duration <= 0.0:
            continue
        for length, v, a, j in _shape(duration, v0, v1, smooth):
            segments.append((t, x, v, a / 2.0, j / 6.0, a, j / 2.0))
            x += length * (v + length * (a / 2.0 + length * j / 6.0))
            t += length
    return Profile(
        duration=t,
        distance=x if distance is None else distance,
        final_velocity=final_velocity,
        _boundaries=tuple(segment[0] for segment in segments[1:]),
        _segments=tuple(segments),
    )


def _shape(duration: float, v0: float, v1: float, smooth: float) -> tuple[tuple[float, float, float, float], ...]:
    """(length, start velocity, start acceleration, jerk) pieces of one phase.

    A ramp with jerk time ``tj`` at each end reaches peak acceleration
    ``Δv/(duration - tj)``; its velocity is symmetric about the ramp's middle,
    so it covers the same distance as the straight ramp it replaces.
    """
    if smooth == 0.0 or v0 == v1:
        return ((duration, v0, (v1 - v0) / duration, 0.0),)
    jerk_time = smooth * duration / 2.0
    peak = (v1 - v0) / (duration - jerk_time)
    jerk = peak / jerk_time
    rise = (jerk_time, v0, 0.0, jerk)
    fall = (jerk_time, v1 - peak * jerk_time / 2.0, peak, -jerk)
    steady = duration - 2.0 * jerk_time
    if steady <= 0.0:
        return rise, fall
    return rise, (steady, v0 + peak * jerk_time / 2.0, peak, 0.0), fall
