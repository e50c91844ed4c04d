"""Homing ends with POS 0 on the switch edge or the index edge, by the manual's sequences (spec §5, HM-1..HM-9).

The home switch is a digital input tied to the axis's physical count, like a
real switch; the index pulse repeats every 4000 counts, 20 counts wide, so
counts 0..19, 4000..4019, -4000..-3981 … are on the pulse. The profiler polls
the switch and the index every 2 ms, so a switch edge crossed at ``v``
counts/s is found within one profiler tick of travel (``2 ms · v``) past the
edge; the 500 counts/s creep covers one count per profiler tick, so an index
edge is found exactly, on the first count off the pulse. Every datum reads
POS 0 exactly, and ENCODER (never zeroed by homing) shows where it is.

``simulate`` runs every program twice, skipping idle ticks and tick by tick,
and asserts that both runs agree.
"""

from __future__ import annotations

from dataclasses import replace

from mintlang.runtime.controller import Controller
from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import RunResult, run_source
from mintlang.runtime.simulation import Limits
from tests.runtime.running import observable, simulate

SWITCH_BELOW = "REM @sim input 5 when enc 0 <= -2000\nHOMEINPUT.0 = 5\n"  # the switch for a negative seek
SWITCH_ABOVE = "REM @sim input 5 when enc 0 >= 3000\nHOMEINPUT.0 = 5\n"  # the switch for a positive seek
INDEX = "REM @sim index 0 every 4000 width 20\n"
SLOW_BACK_OFF = "HOMESPEED.0 = 5000 : HOMEBACKOFF.0 = 10\n"  # back off at 500 counts/s: one count a profiler tick
REPORT = 'PAUSE IDLE.0\nPRINT POS.0, " ", ENCODER.0, " ", HOMEPOS.0, " ", AXISMODE.0, " ", HOME.0, " ", FOLERROR.0\n'

# Every phase the program saw, printed each time HOME reads a new value, then the reading once it is over.
PHASES = """DIM seen = -1
DIM phase = 0
REPEAT
  phase = HOME.0
  IF phase <> seen DO
    seen = phase
    PRINT seen
  ENDIF
UNTIL phase = 0
PRINT "homed ", AXISMODE.0, " ", POS.0
"""


def report(result: RunResult) -> tuple[float, ...]:
    """(POS, ENCODER, HOMEPOS, AXISMODE, HOME, FOLERROR) as the program printed them after homing."""
    assert result.stop.reason is StopReason.END, result.stop.message
    return tuple(float(word) for word in result.terminal.split("\n")[-2].split())


# ------------------------------------------------------------------- datum on the switch (HM-3)


def test_mode_0_backs_off_the_switch_and_zeroes_pos_within_one_profiler_tick_of_the_edge() -> None:
    # Negative seek at 40000 counts/s, back off at 4000 counts/s: the first count off the switch is -1999 and
    # the datum lies within 2 ms * 4000 counts/s = 8 counts of it, in the back-off direction.
    pos, encoder, homepos, axismode, phase, folerror = report(simulate(SWITCH_BELOW + "HOME.0 = 0\n" + REPORT))
    assert (pos, axismode, phase, folerror) == (0, 0, 0, 0)
    assert -1999 <= encoder <= -1999 + 8
    assert homepos == encoder  # POS was ENCODER before homing zeroed it


def test_a_back_off_of_one_count_per_profiler_tick_stops_exactly_on_the_first_count_off_the_switch() -> None:
    assert report(simulate(SWITCH_BELOW + SLOW_BACK_OFF + "HOME.0 = 0\n" + REPORT)) == (0, -1999, -1999, 0, 0, 0)


def test_mode_2_seeks_positive_and_backs_off_negative() -> None:
    assert report(simulate(SWITCH_ABOVE + SLOW_BACK_OFF + "HOME.0 = 2\n" + REPORT)) == (0, 2999, 2999, 0, 0, 0)


def test_the_constant_names_the_mode() -> None:
    source = SWITCH_ABOVE + SLOW_BACK_OFF + "HOME.0 = _hmPOSITIVE_SWITCH\n" + REPORT
    assert report(simulate(source)) == (0, 2999, 2999, 0, 0, 0)


def test_homepos_is_the_position_before_it_was_zeroed_in_user_units() -> None:
    # POS read 1000 counts more than ENCODER before homing, and SCALE 10 then made 10 counts one unit:
    # the datum at count -1999 was POS (-1999 + 1000) / 10
    source = SWITCH_BELOW + SLOW_BACK_OFF + "POS.0 = 1000\nSCALE.0 = 10\nHOME.0 = 0\n" + REPORT
    assert report(simulate(source)) == (0, -1999, -99.9, 0, 0, 0)


def test_the_back_off_runs_at_homespeed_divided_by_homebackoff() -> None:
    # [000:11520-11525]: HOMEBACKOFF = 2, HOMESPEED = 2000 backs off at 1000 counts/s (here from 500 counts
    # inside the switch, which takes half a second)
    source = SWITCH_BELOW + "MOVEA.0 = -2500 : GO.0\nPAUSE IDLE.0\nHOMEBACKOFF.0 = 2 : HOMESPEED.0 = 2000\nHOME.0 = 0\n"
    source += 'PAUSE VEL.0 > 0\nWAIT = 50\nPRINT VEL.0, " ", HOME.0\n'
    assert simulate(source).terminal == "1000 2\n"


def test_a_switch_already_active_at_the_start_goes_straight_to_backing_off() -> None:
    # [000:11469-11471]: no seek, so HOME never reads 1 and the axis never moves further onto the switch
    source = SWITCH_BELOW + SLOW_BACK_OFF + "MOVEA.0 = -2500 : GO.0\nPAUSE IDLE.0\nPRINT HOMESWITCH.0\n"
    source += "HOME.0 = 0\nDIM lowest = 0\nWHILE AXISMODE.0 = 32\n  IF ENCODER.0 < lowest THEN lowest = ENCODER.0\n"
    source += '  IF HOME.0 <> 2 THEN PRINT "phase ", HOME.0\nENDW\nPRINT lowest\n' + REPORT
    result = simulate(source)
    assert result.terminal.split("\n")[:2] == ["1", "-2500"]
    assert report(result) == (0, -1999, -1999, 0, 0, 0)


def test_the_switch_cleared_while_braking_is_passed_again_and_the_datum_is_where_it_clears() -> None:
    # HM-3 5: a cam switch 100 counts wide is crossed at 40000 counts/s, and the 2667 counts needed to stop
    # leave the axis beyond it. It turns round, crosses the cam again at the back-off speed and crash-stops
    # within one profiler tick (8 counts) past the cam's near edge -1999, not where it first found the cam clear.
    source = "HOMEINPUT.0 = 5\nHOME.0 = 0\nDIM lowest = 0\nWHILE AXISMODE.0 = 32\n"
    source += "  IF ENCODER.0 < lowest THEN lowest = ENCODER.0\nENDW\nPRINT lowest\n" + REPORT
    result = run_with_cam(source, channel=5, low=-2100, high=-2000)
    lowest = float(result.terminal.split("\n")[0])
    assert lowest < -2100 - 2000  # it braked well beyond the cam
    pos, encoder, homepos, axismode, phase, folerror = report(result)
    assert (pos, axismode, phase, folerror) == (0, 0, 0, 0)
    assert -1999 <= encoder <= -1999 + 8
    assert homepos == encoder


# ------------------------------------------------------------------- datum on the index (HM-4, HM-5)


def test_mode_1_clears_the_switch_then_creeps_back_onto_the_index_and_stops_on_its_first_count_off() -> None:
    # Back off positive from the switch at -2000, find the pulse at 0..19, brake, creep negative: off at -1.
    assert report(simulate(SWITCH_BELOW + INDEX + "HOME.0 = 1\n" + REPORT)) == (0, -1, -1, 0, 0, 0)


def test_mode_3_is_mode_1_mirrored() -> None:
    # Back off negative from the switch at 3000, find the pulse at 19..0, brake, creep positive: off at 20.
    assert report(simulate(SWITCH_ABOVE + INDEX + "HOME.0 = 3\n" + REPORT)) == (0, 20, 20, 0, 0, 0)


def test_mode_4_seeks_the_index_negative_and_creeps_back_positive() -> None:
    source = INDEX + "MOVEA.0 = 1000 : GO.0\nPAUSE IDLE.0\nHOME.0 = 4\n" + REPORT
    assert report(simulate(source)) == (0, 20, 20, 0, 0, 0)


def test_mode_6_seeks_the_index_positive_and_creeps_back_negative() -> None:
    source = INDEX + "MOVEA.0 = 1000 : GO.0\nPAUSE IDLE.0\nHOME.0 = 6\n" + REPORT
    assert report(simulate(source)) == (0, 3999, 3999, 0, 0, 0)


def test_index_modes_need_no_home_input() -> None:
    assert simulate(INDEX + "HOME.0 = 6\n" + REPORT).stop.reason is StopReason.END


# ------------------------------------------------------------------- phases and state while homing (HM-7, HM-8)


def test_a_program_sees_every_phase_of_a_switch_and_index_cycle_in_order() -> None:
    assert simulate(SWITCH_BELOW + INDEX + "HOME.0 = 1\n" + PHASES).terminal == "1\n2\n3\n4\n5\n0\nhomed 0 0\n"


def test_a_switch_cycle_reads_searching_then_found_home() -> None:
    assert simulate(SWITCH_BELOW + "HOME.0 = 0\n" + PHASES).terminal == "1\n2\n0\nhomed 0 0\n"


def test_an_index_cycle_reads_searching_for_z_found_z_then_creep() -> None:
    assert (
        simulate(INDEX + "MOVEA.0 = 1000 : GO.0\nPAUSE IDLE.0\nHOME.0 = 4\n" + PHASES).terminal
        == "3\n4\n5\n0\nhomed 0 0\n"
    )


def test_axismode_shows_homing_from_the_moment_home_is_written_and_no_go_is_needed() -> None:
    source = SWITCH_BELOW + 'PRINT HOME.0, " ", AXISMODE.0, " ", IDLE.0\nHOME.0 = 0\n'
    source += 'PRINT HOME.0, " ", AXISMODE.0, " ", IDLE.0\nPAUSE IDLE.0\nPRINT HOME.0, " ", AXISMODE.0, " ", IDLE.0\n'
    assert simulate(source).terminal == "0 0 1\n1 32 0\n0 0 1\n"


def test_homeswitch_reads_the_home_input() -> None:
    source = SWITCH_BELOW + "PRINT HOMESWITCH.0\nMOVEA.0 = -2000 : GO.0\nPAUSE IDLE.0\nPRINT HOMESWITCH.0\n"
    source += "HOMEINPUT.0 = 6\nPRINT HOMESWITCH.0\n"
    assert simulate(source).terminal == "0\n1\n0\n"


def test_homepos_reads_0_before_any_homing() -> None:
    assert simulate("PRINT HOMEPOS.0\n").terminal == "0\n"


# ------------------------------------------------------------------- errors (HM-2, HM-8)


def test_a_switch_mode_without_a_home_input_is_error_5() -> None:
    result = simulate("HOME.0 = 0\n")  # HOMEINPUT defaults to -1 (HM-2 RC)
    assert result.stop.reason is StopReason.ERROR
    assert result.stop.message.startswith("R0005")
    assert result.axes[0].axismode == 0


def test_mode_5_is_out_of_range() -> None:
    result = simulate(INDEX + "HOME.0 = 5\n")
    assert result.stop.reason is StopReason.ERROR and result.stop.message.startswith("R0003")


def test_loading_a_move_while_homing_is_error_10() -> None:
    for command in ("MOVER.0 = 100", "JOG.0 = 10", "HOME.0 = 0", "GO.0"):
        result = simulate(SWITCH_BELOW + f"HOME.0 = 0\n{command}\n")
        assert result.stop.reason is StopReason.ERROR, command
        assert result.stop.message.startswith("R0010"), command


def test_homing_again_from_the_datum_finds_the_same_edge_so_homepos_reads_0() -> None:
    # The second cycle starts just clear of the switch, seeks it again and backs off to the same count.
    source = SWITCH_BELOW + SLOW_BACK_OFF + "HOME.0 = 0\nPAUSE IDLE.0\nHOME.0 = 0\n" + REPORT
    assert report(simulate(source)) == (0, -1999, 0, 0, 0, 0)


def test_a_disabled_drive_cannot_home() -> None:
    result = simulate(SWITCH_BELOW + "HOME.0 = 0\n", enable=False)
    assert result.stop.message.startswith("R0040")


# ------------------------------------------------------------------- stopping (HM-8)


def test_stop_ramps_down_at_decel_and_leaves_pos_unzeroed() -> None:
    # Searching at 4000 counts/s for an index that never comes; DECEL 10000 stops it in 800 counts and 400 ms
    # (allowing 2 ms of travel, 8 counts, between reading POS and the profiler tick the ramp starts on).
    source = "DECEL.0 = 10000\nHOME.0 = 4\nWAIT = 500\nDIM before = 0\nbefore = POS.0\nSTOP.0\n"
    source += 'PAUSE IDLE.0\nPRINT before - POS.0, " ", AXISMODE.0, " ", HOME.0, " ", HOMEPOS.0\n'
    moved, axismode, phase, homepos = (float(word) for word in simulate(source).terminal.split())
    assert 800 <= moved <= 808
    assert (axismode, phase, homepos) == (0, 0, 0)


def test_cancel_crash_stops_a_cycle() -> None:
    source = "HOME.0 = 4\nWAIT = 500\nCANCEL.0\nDIM here = 0\nhere = POS.0\nWAIT = 100\n"
    source += 'PRINT POS.0 - here, " ", AXISMODE.0, " ", IDLE.0\n'
    assert simulate(source).terminal == "0 0 1\n"


def test_an_axis_without_index_pulses_searches_until_stopped() -> None:
    source = 'HOME.0 = 6\nWAIT = 5000\nPRINT HOME.0, " ", AXISMODE.0\nSTOP.0\nPAUSE IDLE.0\nPRINT AXISMODE.0\n'
    assert simulate(source).terminal == "3 32\n0\n"


# ------------------------------------------------------------------- tick skipping


def test_skipping_idle_ticks_changes_nothing_in_a_full_cycle() -> None:
    source = SWITCH_BELOW + INDEX + "WAIT = 37\nHOME.0 = 1\n" + PHASES + "WAIT = 1000\n" + REPORT
    limits = Limits(until_ms=60_000)
    skipping = run_source(source, config="RESETALL\n", controller="nextmove-bx", limits=limits)
    stepping = run_source(
        source, config="RESETALL\n", controller="nextmove-bx", limits=replace(limits, every_tick=True)
    )
    assert observable(skipping) == observable(stepping)
    assert report(skipping) == (0, -1, -1, 0, 0, 0)


# ------------------------------------------------------------------- helpers


def run_with_cam(source: str, *, channel: int, low: int, high: int) -> RunResult:
    """Run ``source`` with input ``channel`` active while axis 0's count lies in ``low..high`` (a cam switch,
    which a single ``REM @sim input`` condition cannot express), both skipping ticks and tick by tick.

    The level follows the count at the end of each tick, as position-derived inputs do (T-6 2a).
    """

    def cam(controller: Controller, tick: int) -> None:
        on = low <= controller.axes[0].measured <= high
        world = controller.world
        world.levels = world.levels | 1 << channel if on else world.levels & ~(1 << channel)

    results = [
        run_source(
            source,
            config="RESETALL\n",
            controller="nextmove-bx",
            limits=Limits(until_ms=60_000, every_tick=every_tick),
            on_tick=cam,
        )
        for every_tick in (False, True)
    ]
    assert observable(results[0]) == observable(results[1]), "skipping idle ticks changed the result"
    return results[0]
