"""The motion profiler plans trapezoids, triangles, S-ramps and jog ramps in closed form (spec MP-7..MP-10, MP-16).

The hand-worked cases pin the formulas of spec MP-8; the properties hold for
any speed, rates, distance and start velocity: the speed and rate limits are
kept, the move ends at rest exactly on its target, and its duration is the
closed form's.
"""

from __future__ import annotations

import math
from itertools import pairwise

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mintlang.runtime.motion.profile import Profile, plan_move, plan_velocity, stopping_distance

SPEED, ACCEL, DECEL = 20_000.0, 300_000.0, 300_000.0  # the servo-axis DEFAULTs, spec MP-2 and MP-3
SAMPLES = 1500


def mp8_duration(distance: float, speed: float, accel: float, decel: float) -> float:
    """Spec MP-8 as written: a move from rest to rest of ``distance`` ≥ 0."""
    ramps = speed**2 / (2 * accel) + speed**2 / (2 * decel)
    if distance >= ramps:
        return speed / accel + speed / decel + (distance - ramps) / speed
    peak = math.sqrt(2 * distance * accel * decel / (accel + decel))
    return peak / accel + peak / decel


def expected_duration(distance: float, speed: float, accel: float, decel: float, start: float) -> float:
    """MP-8 extended to a moving start by shifting time, not by re-deriving the phases.

    Entering at ``u`` ≤ ``speed`` is the tail of a move from rest that is
    ``u²/(2·accel)`` longer and started ``u/accel`` earlier. Entering faster
    first sheds the excess at ``decel``; moving away first stops (MP-17);
    too close to stop, the raised deceleration takes ``2·d/u`` (MP-10).
    """
    d, u = (distance, start) if distance > 0 or (distance == 0 and start < 0) else (-distance, -start)
    if u < 0:
        return -u / decel + mp8_duration(d + u**2 / (2 * decel), speed, accel, decel)
    if u**2 >= 2 * decel * d:
        return 2 * d / u if u else 0.0
    if u > speed:
        shed = (u**2 - speed**2) / (2 * decel)
        return (u - speed) / decel + expected_duration(d - shed, speed, accel, decel, speed)
    return mp8_duration(d + u**2 / (2 * accel), speed, accel, decel) - u / accel


def samples(profile: Profile) -> tuple[list[float], list[float], list[float]]:
    """Times, positions and velocities at ``SAMPLES`` + 1 even steps across the whole profile."""
    times = [profile.duration * i / SAMPLES for i in range(SAMPLES + 1)] if profile.duration else [0.0]
    points = [profile.sample(t) for t in times]
    return times, [x for x, _ in points], [v for _, v in points]


def accelerations(profile: Profile) -> list[float]:
    """Finite-difference accelerations between consecutive samples."""
    return [(v1 - v0) / (t1 - t0) for (t0, v0), (t1, v1) in pairwise(zip(*samples(profile)[::2], strict=True))]


def check_rates(profile: Profile, accel: float, decel: float) -> None:
    """Finite differences of velocity respect ``accel`` when |v| grows and ``decel`` when it shrinks."""
    for (t0, v0), (t1, v1) in pairwise(zip(*samples(profile)[::2], strict=True)):
        limit = max(accel, decel) if v0 * v1 < 0 else accel if abs(v1) > abs(v0) else decel
        assert abs(v1 - v0) / (t1 - t0) <= limit * (1 + 1e-6)


class TestTrapezoid:
    def test_default_move_timing_by_hand(self) -> None:
        # Ramps: 20000/300000 = 1/15 s each over 20000²/600000 = 2000/3 counts;
        # the remaining 4000 - 4000/3 = 8000/3 counts cruise at 20000 for 2/15 s.
        profile = plan_move(4000, SPEED, ACCEL, DECEL)
        assert profile.duration == pytest.approx(4 / 15, rel=1e-12)
        assert profile.sample(1 / 15) == pytest.approx((2000 / 3, 20_000), rel=1e-12)
        assert profile.sample(3 / 15) == pytest.approx((4000 - 2000 / 3, 20_000), rel=1e-12)
        assert profile.sample(1 / 30) == pytest.approx((500 / 3, 10_000), rel=1e-12)

    def test_separate_accel_and_decel(self) -> None:
        # Accelerate 0.2 s over 2000 counts, decelerate 0.05 s over 500, cruise 1500 counts for 0.075 s.
        profile = plan_move(4000, 20_000, 100_000, 400_000)
        assert profile.duration == pytest.approx(0.325, rel=1e-12)
        assert profile.sample(0.2) == pytest.approx((2000, 20_000), rel=1e-12)
        assert profile.sample(0.275) == pytest.approx((3500, 20_000), rel=1e-12)

    def test_triangle_when_too_short_to_reach_speed(self) -> None:
        # 1000 counts < 4000/3 needed for full speed: peak sqrt(2·1000·300000²/600000) = sqrt(3·10⁸).
        profile = plan_move(1000, SPEED, ACCEL, DECEL)
        peak = math.sqrt(3e8)
        assert profile.duration == pytest.approx(2 * peak / ACCEL, rel=1e-12)
        assert profile.sample(peak / ACCEL) == pytest.approx((500, peak), rel=1e-12)

    def test_negative_distance_mirrors(self) -> None:
        forward, backward = plan_move(4000, SPEED, ACCEL, DECEL), plan_move(-4000, SPEED, ACCEL, DECEL)
        assert backward.duration == forward.duration
        for t in (0.01, 0.1, 0.2, 0.26):
            x, v = forward.sample(t)
            assert backward.sample(t) == pytest.approx((-x, -v), rel=1e-12)

    def test_rests_exactly_on_target_once_over(self) -> None:
        profile = plan_move(1234.5, SPEED, ACCEL, DECEL)
        assert profile.sample(profile.duration) == (1234.5, 0.0)
        assert profile.sample(profile.duration + 10) == (1234.5, 0.0)
        assert profile.distance == 1234.5

    def test_zero_move_takes_no_time(self) -> None:
        profile = plan_move(0, SPEED, ACCEL, DECEL)
        assert profile.duration == 0
        assert profile.sample(0) == (0, 0)


class TestMovingStart:
    def test_faster_than_speed_sheds_the_excess_at_decel(self) -> None:
        # 30000 → 20000 at DECEL takes 1/30 s over 2500/3 counts; the final ramp takes 2000/3 counts.
        profile = plan_move(4000, SPEED, ACCEL, DECEL, start_velocity=30_000)
        cruise = (4000 - 2500 / 3 - 2000 / 3) / SPEED
        assert profile.duration == pytest.approx(1 / 30 + cruise + 1 / 15, rel=1e-12)
        assert profile.sample(1 / 30) == pytest.approx((2500 / 3, SPEED), rel=1e-12)

    def test_too_close_to_stop_raises_the_deceleration(self) -> None:
        # Stopping at DECEL from 20000 needs 2000/3 counts; within 100 it stops at 20000²/200 = 2·10⁶ counts/s².
        profile = plan_move(100, SPEED, ACCEL, DECEL, start_velocity=SPEED)
        assert profile.duration == pytest.approx(0.01, rel=1e-12)
        assert profile.sample(0.005) == pytest.approx((75, 10_000), rel=1e-12)
        _, positions, _ = samples(profile)
        assert max(positions) <= 100

    def test_target_behind_stops_then_returns(self) -> None:
        # The INCR example of spec MP-17: moving forward, the end point drops behind the axis.
        profile = plan_move(-45, SPEED, ACCEL, DECEL, start_velocity=SPEED)
        assert profile.sample(SPEED / DECEL) == pytest.approx((2000 / 3, 0), abs=1e-9)
        assert profile.sample(profile.duration) == (-45, 0.0)
        assert profile.duration == pytest.approx(1 / 15 + mp8_duration(2000 / 3 + 45, SPEED, ACCEL, DECEL), rel=1e-12)

    def test_moving_on_the_target_comes_back_to_it(self) -> None:
        profile = plan_move(0, SPEED, ACCEL, DECEL, start_velocity=-SPEED)
        _, positions, _ = samples(profile)
        assert min(positions) == pytest.approx(-2000 / 3)
        assert profile.sample(profile.duration) == (0, 0.0)

    @pytest.mark.parametrize("velocity", [20_000.0, -7_000.0])
    def test_stopping_distance_plans_a_pure_stop(self, velocity: float) -> None:
        distance = stopping_distance(velocity, DECEL)
        assert distance == pytest.approx(math.copysign(velocity**2 / (2 * DECEL), velocity))
        profile = plan_move(distance, SPEED, ACCEL, DECEL, start_velocity=velocity)
        assert profile.duration == pytest.approx(abs(velocity) / DECEL, rel=1e-12)


class TestSRamp:
    @pytest.mark.parametrize("sramp", [10.0, 50.0, 100.0])
    @pytest.mark.parametrize("distance", [4000.0, -300.0])
    def test_ends_on_target_later_than_the_trapezoid(self, sramp: float, distance: float) -> None:
        smooth = plan_move(distance, SPEED, ACCEL, DECEL, sramp=sramp)
        assert smooth.duration > plan_move(distance, SPEED, ACCEL, DECEL).duration
        assert smooth.sample(smooth.duration) == (distance, 0.0)
        assert smooth.sample(smooth.duration * (1 - 1e-12))[0] == pytest.approx(distance, rel=1e-9)

    def test_accel_is_the_peak_and_ramps_take_longer_by_the_jerk_phases(self) -> None:
        # SRAMP 50: a quarter of each ramp rises at constant jerk, a quarter falls; the ramp
        # averages 3/4 of ACCEL, so it is the trapezoid planned at 225000 counts/s².
        smooth = plan_move(4000, SPEED, ACCEL, DECEL, sramp=50)
        assert smooth.duration == pytest.approx(mp8_duration(4000, SPEED, 225_000, 225_000), rel=1e-12)
        rates = accelerations(smooth)
        assert max(rates) == pytest.approx(ACCEL, rel=1e-3)
        assert min(rates) == pytest.approx(-DECEL, rel=1e-3)
        check_rates(smooth, ACCEL, DECEL)
        assert smooth.sample(SPEED / 225_000 / 2)[1] == pytest.approx(SPEED / 2, rel=1e-12)

    def test_acceleration_is_continuous(self) -> None:
        profile = plan_move(4000, SPEED, ACCEL, DECEL, sramp=100)
        # At SRAMP 100 the jerk phases are the whole ramp: ACCEL is reached in half of the 2·SPEED/ACCEL ramp.
        jerk = ACCEL / (SPEED / ACCEL)
        rates = accelerations(profile)
        assert max(abs(r1 - r0) for r0, r1 in pairwise(rates)) <= jerk * profile.duration / SAMPLES * (1 + 1e-6)


class TestJog:
    def test_speeds_up_at_accel(self) -> None:
        profile = plan_velocity(0, 15_000, ACCEL, 100_000)
        assert profile.duration == pytest.approx(0.05, rel=1e-12)
        assert profile.sample(0.025) == pytest.approx((93.75, 7_500), rel=1e-12)

    def test_slows_down_at_decel(self) -> None:
        profile = plan_velocity(15_000, 5_000, ACCEL, 100_000)
        assert profile.duration == pytest.approx(0.1, rel=1e-12)

    def test_reversal_stops_at_decel_then_speeds_up_at_accel(self) -> None:
        profile = plan_velocity(10_000, -6_000, ACCEL, 100_000)
        assert profile.duration == pytest.approx(0.1 + 0.02, rel=1e-12)
        assert profile.sample(0.1) == pytest.approx((500, 0), abs=1e-9)
        assert profile.distance == pytest.approx(500 - 60, rel=1e-12)

    def test_runs_on_for_ever_after_the_ramp(self) -> None:
        profile = plan_velocity(0, -2_000, ACCEL, DECEL)
        x, _ = profile.sample(profile.duration)
        assert profile.sample(profile.duration + 3) == pytest.approx((x - 6_000, -2_000), rel=1e-12)

    def test_already_at_speed_is_no_ramp(self) -> None:
        profile = plan_velocity(1_000, 1_000, ACCEL, DECEL)
        assert profile.duration == 0
        assert profile.sample(2) == (2_000, 1_000)

    def test_jog_zero_ends_at_rest(self) -> None:
        profile = plan_velocity(SPEED, 0, ACCEL, DECEL)
        assert profile.sample(1) == pytest.approx((stopping_distance(SPEED, DECEL), 0))


@pytest.mark.parametrize(
    "arguments",
    [
        {"speed": 0.0},
        {"accel": -1.0},
        {"decel": 0.0},
        {"sramp": 101.0},
        {"sramp": -1.0},
    ],
)
def test_rejects_rates_the_closed_form_cannot_use(arguments: dict[str, float]) -> None:
    with pytest.raises(ValueError):
        plan_move(**({"distance": 100.0, "speed": SPEED, "accel": ACCEL, "decel": DECEL} | arguments))


def signed(smallest: float, largest: float) -> st.SearchStrategy[float]:
    """0, or either sign within the magnitudes a controller meets (none near the float minimum: jerks overflow)."""
    return st.one_of(st.just(0.0), st.floats(-largest, largest).filter(lambda x: abs(x) >= smallest))


speeds = st.floats(1.0, 1e6)
rates = st.floats(10.0, 1e7)
distances = signed(1e-6, 1e6)
start_velocities = signed(1e-6, 2e6)
sramps = st.one_of(st.just(0.0), st.floats(1.0, 100.0))


@settings(max_examples=300, derandomize=True)
@given(distance=distances, speed=speeds, accel=rates, decel=rates, start=start_velocities, sramp=sramps)
def test_any_move_keeps_its_limits_and_lands_on_target(
    *, distance: float, speed: float, accel: float, decel: float, start: float, sramp: float
) -> None:
    profile = plan_move(distance, speed, accel, decel, start, sramp=sramp)
    mean = 1 - sramp / 200
    assert profile.duration == pytest.approx(
        expected_duration(distance, speed, accel * mean, decel * mean, start), rel=1e-9
    )
    assert profile.sample(profile.duration) == (distance, 0.0)
    scale = max(abs(distance), start**2 / decel, 1.0)
    assert profile.sample(profile.duration * (1 - 1e-13))[0] == pytest.approx(distance, rel=0, abs=1e-9 * scale)

    _, positions, velocities = samples(profile)
    assert max(map(abs, velocities)) <= max(speed, abs(start)) * (1 + 1e-9)
    toward = start * distance > 0
    remaining = abs(distance)
    raised = start**2 / (2 * remaining * decel * mean) if toward else 0.0
    check_rates(profile, accel, decel * max(1.0, raised))
    if start * distance >= 0 and distance:
        # Starting at rest or toward the target, the axis never passes it (spec MP-10 RC).
        assert max(x / distance for x in positions) <= 1 + 1e-12


@settings(max_examples=300, derandomize=True)
@given(start_velocities, start_velocities, rates, rates)
def test_any_jog_ramp_is_monotonic_within_its_rates(start: float, target: float, accel: float, decel: float) -> None:
    profile = plan_velocity(start, target, accel, decel)
    if start * target < 0:
        expected = abs(start) / decel + abs(target) / accel
    else:
        expected = abs(target - start) / (accel if abs(target) > abs(start) else decel)
    assert profile.duration == pytest.approx(expected, rel=1e-9)
    _, _, velocities = samples(profile)
    direction = math.copysign(1.0, target - start)
    assert all((v1 - v0) * direction >= -1e-9 * abs(v0) for v0, v1 in pairwise(velocities))
    check_rates(profile, accel, decel)
    assert profile.sample(profile.duration + 1)[1] == target
