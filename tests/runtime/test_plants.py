"""Plant models: what the encoder reads back each servo tick (spec W-1).

The ideal and stalled plants pin the checkable scenarios; the torque plant
makes the servo gains, DACLIMITMAX and following-error trips behave as on a
real motor: no gains, no motion; too little DAC, a growing following error.
"""

from __future__ import annotations

import math

import pytest

from mintlang.runtime.motion.plants import (
    TORQUE_PLANT_GAINS,
    IdealPlant,
    Plant,
    StalledPlant,
    TorquePlant,
    VelocityPlant,
    round_half_away,
)
from mintlang.runtime.motion.profile import plan_move
from mintlang.runtime.motion.servo import ServoGains, ServoLoop

TICK = 0.001  # the NM-REF servo tick, spec T-1
FOLERRORFATAL = 1000  # its default, spec AX-9


@pytest.mark.parametrize(
    ("value", "count"),
    [(0.5, 1), (-0.5, -1), (1.5, 2), (2.5, 3), (-2.5, -3), (0.49999999999999994, 0), (-7.2, -7), (3.0, 3)],
)
def test_round_half_away_from_zero(value: float, count: int) -> None:
    assert round_half_away(value) == count


class TestIdealPlant:
    def test_reads_the_rounded_demand(self) -> None:
        plant = IdealPlant()
        assert [plant.step(d, 0.0, TICK) for d in (0.4, 0.5, -1.5, 1234.49)] == [0, 1, -2, 1234]
        assert not IdealPlant.closed_loop

    def test_holds_while_nothing_servoes_it(self) -> None:
        plant = IdealPlant()
        plant.step(42.0, 0.0, TICK)
        assert plant.step(None, 100.0, TICK) == 42


def test_stalled_plant_never_moves() -> None:
    plant = StalledPlant(7)
    assert {plant.step(d, 100.0, TICK) for d in (0.0, 5000.0, None)} == {7}
    assert not StalledPlant.closed_loop


def test_velocity_plant_turns_at_k_counts_per_second_per_percent() -> None:
    plant = VelocityPlant(1000.0)
    readings = [plant.step(None, 10.0, TICK) for _ in range(1000)]
    assert readings[0] == 10
    assert readings[-1] == 10_000
    assert plant.step(None, 0.0, TICK) == 10_000
    assert VelocityPlant.closed_loop


class TestTorquePlant:
    def test_constant_drive_follows_the_exact_solution(self) -> None:
        # From rest, a = 50000·2 - 10·v - 20000: v(t) = 8000·(1 - e^(-10t)), x(t) = 8000·t - 800·(1 - e^(-10t)).
        plant = TorquePlant()
        for _ in range(500):
            plant.step(None, 2.0, TICK)
        assert plant.velocity == pytest.approx(8000 * (1 - math.exp(-5)), rel=1e-12)
        assert plant.position == pytest.approx(8000 * 0.5 - 800 * (1 - math.exp(-5)), rel=1e-12)

    def test_integration_does_not_depend_on_the_step(self) -> None:
        fine, coarse = TorquePlant(), TorquePlant()
        for _ in range(1000):
            fine.step(None, -30.0, TICK)
        for _ in range(4):
            coarse.step(None, -30.0, 0.25)
        assert coarse.position == pytest.approx(fine.position, rel=1e-12)
        assert coarse.velocity == pytest.approx(fine.velocity, rel=1e-12)

    def test_less_drive_than_friction_does_not_break_away(self) -> None:
        plant = TorquePlant()
        assert {plant.step(None, 0.39, TICK) for _ in range(100)} == {0}
        assert plant.velocity == 0.0

    def test_coasts_to_a_stop_where_friction_says_and_stays(self) -> None:
        # Released at 10000 counts/s: v(t) = 12000·e^(-10t) - 2000 is 0 at t = ln(6)/10,
        # after 10000/10 - 2000·ln(6)/10 counts.
        plant = TorquePlant()
        plant.velocity = 10_000.0
        readings = [plant.step(None, 0.0, TICK) for _ in range(500)]
        assert plant.velocity == 0.0
        assert plant.position == pytest.approx(1000 - 200 * math.log(6), rel=1e-12)
        assert readings[-1] == readings[-200] == round_half_away(plant.position)

    def test_stable_at_any_step(self) -> None:
        plant = TorquePlant()
        plant.step(None, 100.0, 10.0)
        assert plant.velocity == pytest.approx((5e6 - 20_000) / 10, rel=1e-9)

    def test_rejects_a_frictionless_model(self) -> None:
        with pytest.raises(ValueError):
            TorquePlant(viscous=0.0)


def follow(gains: ServoGains, distance: float = 4000.0, milliseconds: int = 600) -> tuple[list[float], int]:
    """Run a default-parameter move on a TorquePlant in servo-tick order; following errors and final count.

    Each tick the plant moves under the DAC written at the tick before and is
    read, then the law computes the next DAC from that reading.
    """
    profile = plan_move(distance, 20_000.0, 300_000.0, 300_000.0)
    plant: Plant = TorquePlant()
    loop = ServoLoop(gains)
    measured, dac, previous_demand, previous_velocity = 0, 0.0, 0.0, 0.0
    errors = []
    for tick in range(1, milliseconds + 1):
        demand, _ = profile.sample(tick * TICK)
        velocity = demand - previous_demand
        previous_measured, measured = measured, plant.step(demand, dac, TICK)
        dac = loop.step(demand, velocity, velocity - previous_velocity, measured, measured - previous_measured)
        errors.append(demand - measured)
        previous_demand, previous_velocity = demand, velocity
    return errors, measured


class TestClosedLoop:
    @pytest.mark.parametrize("distance", [4000.0, -4000.0, 137.0])
    def test_recommended_gains_track_within_a_few_counts(self, distance: float) -> None:
        errors, final = follow(TORQUE_PLANT_GAINS, distance)
        assert max(map(abs, errors)) < 5 < FOLERRORFATAL
        assert final == distance

    def test_zero_gains_leave_the_axis_where_it_is(self) -> None:
        errors, final = follow(ServoGains())
        assert final == 0
        assert errors[-1] == 4000 > FOLERRORFATAL

    def test_starved_dac_lets_the_following_error_grow_past_the_fatal_limit(self) -> None:
        errors, _ = follow(ServoGains(kprop=0.5, kderiv=6.0, kvelff=0.2, kaccel=20.0, daclimitmax=1.0))
        assert max(errors) > FOLERRORFATAL
