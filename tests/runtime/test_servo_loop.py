"""The PIDVFA law term by term, with its clamps and integrator modes (spec SL-1..SL-6).

Demand = KP·e + KD·Δe - KV·v + KF·V + KI·Σe + KA·a in percent of DAC full
scale (SL-3 RC), clamped to ±DACLIMITMAX; KI·Σe is held within ±KINTLIMIT.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.motion.servo import KintMode, ServoGains, ServoLoop


def drive(loop: ServoLoop, error: float, *, velocity: float = 0.0, acceleration: float = 0.0) -> float:
    """One sample with the axis at 0 and the given following error and demand velocity and acceleration."""
    return loop.step(error, velocity, acceleration, 0.0, 0.0)


def test_defaults_are_the_default_table() -> None:
    # DEFAULT zeroes every gain and sets KINTLIMIT and DACLIMITMAX to 100 (spec SL-2, SL-4, SL-6).
    assert ServoLoop().gains == ServoGains(0, 0, 100, KintMode.ALWAYS, 0, 0, 0, 0, 100)


def test_all_zero_gains_apply_nothing() -> None:
    loop = ServoLoop()
    assert loop.step(1000.0, 20.0, 0.3, -5.0, -3.0) == 0.0


class TestEachTermAlone:
    def test_proportional_acts_on_the_following_error(self) -> None:
        loop = ServoLoop(ServoGains(kprop=0.5))
        assert loop.step(110.0, 0.0, 0.0, 100.0, 0.0) == 5.0
        assert loop.step(100.0, 0.0, 0.0, 110.0, 0.0) == -5.0

    def test_derivative_acts_on_the_change_of_error_per_sample(self) -> None:
        loop = ServoLoop(ServoGains(kderiv=2.0))
        assert drive(loop, 10.0) == 20.0
        assert drive(loop, 14.0) == 8.0
        assert drive(loop, 14.0) == 0.0

    def test_velocity_feedback_opposes_the_measured_velocity(self) -> None:
        loop = ServoLoop(ServoGains(kvel=0.25))
        assert loop.step(0.0, 0.0, 0.0, 0.0, 8.0) == -2.0

    def test_velocity_feed_forward_follows_the_demand_velocity(self) -> None:
        loop = ServoLoop(ServoGains(kvelff=0.2))
        assert drive(loop, 0.0, velocity=20.0) == 4.0

    def test_acceleration_feed_forward_follows_the_demand_acceleration(self) -> None:
        loop = ServoLoop(ServoGains(kaccel=20.0))
        assert drive(loop, 0.0, acceleration=-0.3) == pytest.approx(-6.0)

    def test_integral_sums_the_error_every_sample(self) -> None:
        loop = ServoLoop(ServoGains(kint=0.1))
        assert [drive(loop, 10.0) for _ in range(3)] == pytest.approx([1.0, 2.0, 3.0])
        assert loop.integral == pytest.approx(3.0)

    def test_terms_add_up(self) -> None:
        gains = ServoGains(kprop=1, kderiv=2, kvel=3, kvelff=4, kaccel=5, kint=0.5)
        assert ServoLoop(gains).step(10.0, 2.0, 1.0, 7.0, 1.0) == pytest.approx(3 + 6 - 3 + 8 + 5 + 1.5)


class TestClamps:
    @pytest.mark.parametrize("error", [1e6, -1e6])
    def test_output_never_exceeds_full_scale(self, error: float) -> None:
        assert drive(ServoLoop(ServoGains(kprop=1.0)), error) == pytest.approx(100.0 if error > 0 else -100.0)

    def test_daclimitmax_limits_the_output_symmetrically(self) -> None:
        loop = ServoLoop(ServoGains(kprop=1.0, daclimitmax=12.5))
        assert drive(loop, 30.0) == 12.5
        assert drive(loop, -30.0) == -12.5
        assert drive(loop, 5.0) == 5.0

    def test_kintlimit_caps_the_integral_term(self) -> None:
        # The manual's example: KPROP 1, KINTLIMIT 20, KINT 0.1 — integral action is at most 20 % of full scale.
        loop = ServoLoop(ServoGains(kprop=1.0, kint=0.1, kintlimit=20.0))
        for _ in range(1000):
            drive(loop, 10.0)
        assert loop.integral == 20.0
        assert drive(loop, 10.0) == 30.0

    def test_integrator_does_not_wind_up_beyond_the_limit(self) -> None:
        loop = ServoLoop(ServoGains(kint=1.0, kintlimit=25.0))
        assert [drive(loop, 10.0) for _ in range(4)] == [10.0, 20.0, 25.0, 25.0]
        assert drive(loop, -10.0) == 15.0

    def test_lowering_kintlimit_takes_effect_at_once(self) -> None:
        loop = ServoLoop(ServoGains(kint=1.0))
        for _ in range(5):
            drive(loop, 10.0)
        loop.gains = ServoGains(kint=1.0, kintlimit=5.0)
        assert drive(loop, 0.0) == 5.0


class TestKintMode:
    def test_never_keeps_the_integrator_empty(self) -> None:
        loop = ServoLoop(ServoGains(kint=1.0, kintmode=KintMode.NEVER))
        assert drive(loop, 10.0) == 0.0
        assert loop.integral == 0.0

    def test_always_integrates_during_motion(self) -> None:
        loop = ServoLoop(ServoGains(kint=1.0, kintmode=KintMode.ALWAYS))
        drive(loop, 10.0, velocity=5.0, acceleration=1.0)
        assert loop.integral == 10.0

    def test_at_rest_integrates_only_without_demand_velocity_and_holds_otherwise(self) -> None:
        loop = ServoLoop(ServoGains(kint=1.0, kintmode=KintMode.AT_REST))
        drive(loop, 10.0)
        assert drive(loop, 7.0, velocity=3.0) == 10.0
        assert drive(loop, 7.0, velocity=3.0, acceleration=0.5) == 10.0
        assert drive(loop, 2.0) == 12.0

    def test_smart_integrates_only_at_constant_non_zero_velocity(self) -> None:
        loop = ServoLoop(ServoGains(kint=1.0, kintmode=KintMode.SMART))
        assert drive(loop, 10.0) == 0.0
        assert drive(loop, 10.0, velocity=3.0, acceleration=0.2) == 0.0
        assert drive(loop, 10.0, velocity=3.0) == 10.0
        assert drive(loop, 4.0, velocity=-3.0, acceleration=-0.2) == 10.0

    def test_zero_kint_empties_the_integrator(self) -> None:
        loop = ServoLoop(ServoGains(kint=1.0))
        drive(loop, 10.0)
        loop.gains = ServoGains()
        assert drive(loop, 10.0) == 0.0
        loop.gains = ServoGains(kint=1.0)
        assert drive(loop, 1.0) == 1.0


def test_history_survives_retuning_and_reset_forgets_it() -> None:
    loop = ServoLoop(ServoGains(kint=1.0, kderiv=1.0))
    drive(loop, 10.0)
    loop.gains = ServoGains(kint=1.0, kderiv=1.0, kprop=1.0)
    assert drive(loop, 10.0) == 10.0 + 0.0 + 20.0
    loop.reset()
    assert loop.integral == 0.0
    assert drive(loop, 10.0) == 10.0 + 10.0 + 10.0


class TestSettled:
    """Whether samples at rest would change nothing, so the simulator may skip them (a stalled axis at rest)."""

    def test_a_proportional_loop_is_settled_once_the_derivative_has_acted(self) -> None:
        loop = ServoLoop(ServoGains(kprop=0.5, kderiv=2.0))
        output = drive(loop, 10.0)  # the derivative acts on the step from 0 to 10 this sample only
        assert not loop.settled(10.0, 0.0, output)
        output = drive(loop, 10.0)
        assert output == 5.0 and loop.settled(10.0, 0.0, output)

    def test_an_integrator_is_settled_only_once_it_reaches_kintlimit(self) -> None:
        loop = ServoLoop(ServoGains(kint=0.5, kintlimit=20.0))
        outputs = [drive(loop, 10.0) for _ in range(4)]
        assert outputs == [5.0, 10.0, 15.0, 20.0]
        assert loop.settled(10.0, 0.0, 20.0)
        assert not loop.settled(0.0, 10.0, 20.0)  # an error the other way unwinds it

    def test_retuning_unsettles_the_loop(self) -> None:
        loop = ServoLoop(ServoGains(kprop=0.5))
        output = drive(loop, 10.0)
        loop.gains = ServoGains(kprop=1.0)
        assert not loop.settled(10.0, 0.0, output)

    def test_asking_changes_nothing(self) -> None:
        loop = ServoLoop(ServoGains(kint=0.1, kderiv=1.0))
        drive(loop, 10.0)
        loop.settled(10.0, 0.0, 0.0)
        assert (loop.integral, drive(loop, 10.0)) == (pytest.approx(1.0), pytest.approx(2.0))
