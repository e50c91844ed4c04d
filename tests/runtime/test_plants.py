"""Plant models: what the encoder reads back each servo tick (spec W-1).

The ideal and stalled plants pin the checkable scenarios; the torque plant
makes the servo gains, DACLIMITMAX and following-error trips behave as on a
real motor: no gains, no motion; too little DAC, a growing following error.
A stalled axis still runs the servo law, so its DAC shows the controller
pushing against the jam.
"""

from __future__ import annotations

import math

import pytest

from mintlang.runtime.interpreter.vm import StopReason
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
from tests.runtime.running import simulate

TICK = 0.001  # the NM-REF servo tick, spec T-1
FOLERRORFATAL = 1000  # its default, spec AX-9
_OPEN_LOOP = "DRIVEENABLE.0 = 0 : CONFIG.0 = _cfOFF : DRIVEENABLE.0 = 1\n"  # CONFIG needs the drive off (000:8481)


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


class TestStalledAxisServoes:
    """The law runs on the real following error of a jammed axis: its DAC grows with it and saturates (SL-1, SL-3)."""

    STALLED = "REM @sim plant 0 stalled\n"

    @pytest.mark.parametrize("distance", [200, -200])
    def test_the_dac_is_kprop_times_the_following_error(self, distance: int) -> None:
        # KPROP 0.25 alone: once the move has ended the error is the whole distance, so DAC = 0.25·distance.
        source = self.STALLED + f"KPROP.0 = 0.25\nMOVER.0 = {distance} : GO.0\nWAIT = 500\n"
        source += 'PRINT FOLERROR.0, " ", DAC.0\n'
        assert simulate(source).terminal == f"{distance} {distance // 4}\n"

    @pytest.mark.parametrize("distance", [2000, -2000])
    def test_mid_move_the_dac_pushes_toward_the_demand(self, distance: int) -> None:
        source = self.STALLED + f"KPROP.0 = 0.25\nMOVER.0 = {distance} : GO.0\nPAUSE IDLE.0\n"
        axis = simulate(source, until_ms=31).axes[0]
        assert axis.pos == 0 and 0 < abs(axis.dac) < 100
        assert math.copysign(1.0, axis.dac) == math.copysign(1.0, distance)
        assert axis.dac == 0.25 * axis.folerror

    @pytest.mark.parametrize(("distance", "dac"), [(4000, 30.0), (-4000, -30.0)])
    def test_a_large_following_error_saturates_the_dac_at_daclimitmax(self, distance: int, dac: float) -> None:
        source = self.STALLED + "KPROP.0 = 1 : DACLIMITMAX.0 = 30 : FOLERRORFATAL.0 = 5000\n"
        source += f"MOVER.0 = {distance} : GO.0\nWAIT = 500\n"
        axis = simulate(source).axes[0]
        assert (axis.folerror, axis.dac) == (distance, dac)

    def test_the_following_error_trips_with_the_dac_saturated_and_cancel_stops_the_push(self) -> None:
        # FOLERRORMODE 2 crash-stops and leaves the drive on; CANCEL sets demand = measured (SL-10).
        source = self.STALLED + "KPROP.0 = 1 : DACLIMITMAX.0 = 30 : FOLERRORFATAL.0 = 100 : FOLERRORMODE.0 = 2\n"
        source += 'MOVER.0 = 2000 : GO.0\nPAUSE IDLE.0\nWAIT = 2\nPRINT "after ", DAC.0\nEND\n'
        source += '#ONERROR\nPRINT AXISERROR.0, " ", DRIVEENABLE.0, " ", DAC.0\nCANCEL.0\nRETURN\n'
        assert simulate(source).terminal == "32 1 30\nafter 0\n"

    def test_the_integrator_winds_up_at_rest_to_kintlimit_every_tick(self) -> None:
        # At rest the error is 100 counts, so KI·Σe grows by 0.001·100 = 0.1 % a tick until it reaches KINTLIMIT;
        # the idle ticks in between are processed, not skipped (``simulate`` checks both ways agree).
        source = self.STALLED + "KINT.0 = 0.001 : KINTLIMIT.0 = 50\nMOVER.0 = 100 : GO.0\nPAUSE AXISMODE.0 = 0\n"
        source += "WAIT = 2000\n"
        early, later, settled = (simulate(source, until_ms=ms).axes[0].dac for ms in (200, 300, 3000))
        assert later - early == pytest.approx(10.0, rel=1e-6)
        assert settled == 50.0

    def test_a_program_waiting_on_nothing_is_a_deadlock_once_the_integrator_is_full(self) -> None:
        source = self.STALLED + "KINT.0 = 0.001 : KINTLIMIT.0 = 50\nMOVER.0 = 100 : GO.0\nPAUSE IN.1\n"
        result = simulate(source)
        assert result.stop.reason is StopReason.DEADLOCK
        assert result.axes[0].dac == 50.0

    def test_enabling_the_drive_again_restarts_the_law_where_the_axis_is(self) -> None:
        # SL-10: demand := measured on enable, so the error from before the drive went off is not pushed against
        source = self.STALLED + "KPROP.0 = 0.25 : KINT.0 = 0.001\nMOVER.0 = 200 : GO.0\nWAIT = 500\n"
        source += 'DRIVEENABLE.0 = 0\nDRIVEENABLE.0 = 1\nWAIT = 10\nPRINT FOLERROR.0, " ", DAC.0\n'
        assert simulate(source).terminal == "0 0\n"

    def test_a_dac_written_on_an_axis_configured_off_holds(self) -> None:
        source = self.STALLED + "KPROP.0 = 1\n" + _OPEN_LOOP + "DAC.0 = 25\nMOVER.0 = 500 : GO.0\nWAIT = 50\n"
        assert simulate(source).axes[0].dac == 25.0


class TestDacWrittenOnAnAxisConfiguredOff:
    """000:8756-8762: DAC.0 = -50 on an axis configured off is -5 V out, and DAC reads back what the
    output is on any axis (SL-11), on the default ideal plant and drive, with or without ticks between. As in the
    guide's example, the drive is as at power-up: disabled, as CONFIG needs it (000:8481)."""

    def test_reads_back_at_once(self) -> None:
        result = simulate("CONFIG.0 = _cfOFF : DAC.0 = -50 : PRINT DAC.0\n", enable=False)
        assert result.terminal == "-50\n"
        assert result.axes[0].dac == -50.0

    def test_holds_while_the_program_waits(self) -> None:
        assert simulate("CONFIG.0 = _cfOFF : DAC.0 = -50\nWAIT = 5\nPRINT DAC.0\n", enable=False).terminal == "-50\n"


def test_velocity_plant_turns_at_k_counts_per_second_per_percent() -> None:
    plant = VelocityPlant(1000.0)
    readings = [plant.step(None, 10.0, TICK) for _ in range(1000)]
    assert readings[0] == 10
    assert readings[-1] == 10_000
    assert plant.step(None, 0.0, TICK) == 10_000
    assert VelocityPlant.closed_loop


def test_a_dac_written_on_an_axis_configured_off_drives_a_velocity_amplifier() -> None:
    # SL-11: the program's DAC, not the servo law, drives the amplifier: 10 % at 1000 counts/s per %.
    source = "REM @sim plant 0 velamp 1000\nKPROP.0 = 1\n" + _OPEN_LOOP + "DAC.0 = 10\nWAIT = 100\n"
    axis = simulate(source).axes[0]
    assert (axis.dac, axis.vel) == (10.0, 10_000.0)
    assert axis.pos == 0.0  # a NextMove axis turned off counts no position, its encoder turns (000:15126-15127)


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
