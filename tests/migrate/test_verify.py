"""``verify``: the v3 original and its migration run side by side, and what the comparison says.

Expected values are worked out by hand. The simulator's profiler follows a
trapezoid (runtime/BEHAVIOUR.md); a move of D counts at speed V and rate A
accelerates for V/A s over V²/2A counts, cruises, and decelerates the same way.
Times carry the few ms a move takes to start (the 2 ms profiler, the first
tick's slice) and a measured velocity takes to follow, stated as a bound.
"""

from __future__ import annotations

from dataclasses import replace
from unittest import mock

from mintlang.migrate import ManualItem, MigrationResult, migrate
from mintlang.migrate.rules import renames
from mintlang.migrate.verification import Place, Verdict, verify
from mintlang.runtime.scenario import AdcLevel, DrivesEnabled, InputLevel, Scenario

DRIVES = Scenario(drives=(DrivesEnabled(),))

# SCALE 10 counts a unit; SPEED 100 units/s and ACCEL 1000 units/s² (DECEL too, in v3): 0.1 s to speed
# over 5 units, 40 units at 100 units/s (0.4 s), 5 units to stop: the move takes 600 ms.
PRINTS_AND_MOVES = """SCALE = 10
SPEED = 100 : ACCEL = 1000
PRINT "go"
MOVEA.0 = 50 : GO.0
PAUSE IDLE.0
PRINT POS.0
"""


def _line_of(result: MigrationResult, text: str) -> int:
    """The line of the migrated program that starts with ``text`` (the migrator adds notes, AXES and DIM above)."""
    return next(number for number, line in enumerate(result.text.splitlines(), 1) if line.startswith(text))


def test_an_exact_migration_of_a_program_that_prints_and_moves_is_equivalent_over_the_whole_run() -> None:
    result = migrate(PRINTS_AND_MOVES)
    found = verify(result, scenario=DRIVES, until_ms=5000)
    assert found.verdict is Verdict.EQUIVALENT
    assert found.divergence is None and found.differences == ()
    assert 600 <= found.compared_ms <= 604  # the 600 ms move, then both programs end
    assert (found.v3_stop.reason, found.v4_stop.reason) == ("end", "end")
    assert found.v3_stop.line == Place("program", 6)
    assert found.v4_stop.line == Place("program", _line_of(result, "PRINT POS.0"))


def test_numbers_v3_prints_to_three_places_in_256ths_compare_with_v4s_four() -> None:
    # 1/3 is 85/256 = 0.33203 in v3, printed 0.332 (V3-2, V3-4); v4 prints 0.3333 (X-PRINT)
    found = verify(migrate("PRINT 1/3\n"), until_ms=100)
    assert found.verdict is Verdict.EQUIVALENT


def test_the_guides_joystick_reads_zero_speed_at_rest_after_migration() -> None:
    # v3:4374-4380: JOG = A1 - 512 is zero speed at 0 V; one part in 1024 (v3:4368), so 50 % of +10 V
    # reads (50 + 100) * 1024 / 200 = 768 in both runs
    program = 'WAIT = 2\nPRINT A1 - 512, " ", A2\n'
    levels = Scenario(adc=(AdcLevel(time_ms=0, channel=0, percent=0), AdcLevel(time_ms=0, channel=1, percent=50)))
    found = verify(migrate(program), scenario=levels, until_ms=100)
    assert found.verdict is Verdict.EQUIVALENT


def test_a_swapped_rename_is_reported_at_the_time_and_lines_it_shows() -> None:
    # A wrong M-REN rule: HMSPEED becomes SPEED, so the v4 move cruises at 5000 counts/s, not 20000.
    # At 100000 counts/s² both reach 5000 after 50 ms; v3 goes on. Its velocity leaves the tube around
    # v4's once v3(t - 2 ms) - 5000 > 1% of it + 1000 counts/s: 100(t - 2) - 5000 > t + 1000, t > 62.6 ms.
    program = "SPEED = 20000 : ACCEL = 100000\nHMSPEED = 5000\nMOVEA.0 = 100000 : GO.0\nPAUSE IDLE.0\n"
    wrong = dict(renames.KEYWORD_RENAMES, HMSPEED=("SPEED", 11357))
    with mock.patch.object(renames, "KEYWORD_RENAMES", wrong):
        result = migrate(program)
    found = verify(result, scenario=DRIVES, until_ms=3000)
    assert found.verdict is Verdict.DIVERGES
    divergence = found.divergence
    assert divergence is not None
    assert divergence.what == "axis 0 velocity"
    assert 63 <= divergence.time_ms <= 68
    assert float(divergence.v4) == 5000
    assert float(divergence.v3) > 6000
    assert divergence.v3_line == Place("program", 4)  # both programs wait in their PAUSE IDLE.0
    assert divergence.v4_line == Place("program", _line_of(result, "PAUSE IDLE.0"))
    assert not divergence.timing_only


def test_a_changed_print_is_a_terminal_divergence_at_the_line_that_printed_it() -> None:
    result = migrate(PRINTS_AND_MOVES)
    altered = replace(result, text=result.text.replace('PRINT "go"', 'PRINT "GO"'))
    divergence = verify(altered, scenario=DRIVES, until_ms=1000).divergence
    assert divergence is not None
    assert (divergence.time_ms, divergence.what) == (0, "terminal")
    assert (divergence.v3, divergence.v4) == ("'go'", "'GO'")
    assert divergence.detail == "v3 character 1 / v4 character 1"
    assert divergence.v3_line == Place("program", 3)
    assert divergence.v4_line == Place("program", _line_of(result, 'PRINT "go"'))


def test_a_v3_default_v4_changed_diverges_where_the_speeds_part() -> None:
    # No SPEED: v3's default is 40000 counts/s, v4's 20000 (S-DEFAULTS, a note to fill in); ACCEL is
    # 300000 counts/s² in both. v4 cruises from 66.7 ms; v3 leaves the tube once
    # 300(t - 2) - 20000 > 3t + 1000, t > 72.7 ms.
    result = migrate("MOVEA.0 = 100000 : GO.0 : PAUSE IDLE.0\n")
    found = verify(result, scenario=DRIVES, until_ms=3000)
    assert found.verdict is Verdict.DIVERGES
    assert found.divergence is not None
    assert found.divergence.what == "axis 0 velocity"
    assert 73 <= found.divergence.time_ms <= 78
    assert float(found.divergence.v4) == 20000
    speed_note = [item for _, item in found.not_verified if item.rule == "S-DEFAULTS" and "SPEED" in item.reason]
    assert speed_note and speed_note[0].note


def test_output_a_blocking_v3_go_delayed_is_a_timing_difference_x_go_timing_flagged() -> None:
    # v3: the second GO waits for the first 10000-count move (200 ms up to 20000 counts/s over 2000
    # counts, 6000 at speed in 300 ms, 200 ms down: 700 ms), so OUT0 is set at about 700 ms; v4's GO
    # does not wait and sets it in the first tick. Both moves and both ends are the same.
    program = "SPEED = 20000 : ACCEL = 100000\nMOVER.0 = 10000 : GO.0\nMOVER.0 = 10000 : GO.0\nOUT0 = 1\nPAUSE IDLE.0\n"
    result = migrate(program)
    found = verify(result, scenario=DRIVES, until_ms=3000)
    assert found.verdict is Verdict.TIMING
    assert [divergence.what for divergence in found.differences] == ["OUT bit 0"]
    divergence = found.divergence
    assert divergence is not None
    assert (divergence.time_ms, divergence.v3, divergence.v4) == (0, "0", "1")
    assert divergence.timing_only
    assert divergence.v3_line == Place("program", 3)  # waiting in its second GO
    assert 1400 <= found.v3_stop.time_ms <= 1404 and 1400 <= found.v4_stop.time_ms <= 1404
    timing = [item for unit, item in found.not_verified if item.rule == "X-GO-TIMING"]
    assert [(item.original_line, item.line) for item in timing] == [(4, _line_of(result, "OUT0 = 1"))]


def test_every_statement_left_for_a_person_is_listed_as_not_verified() -> None:
    result = migrate(PRINTS_AND_MOVES)
    found = verify(result, scenario=DRIVES, until_ms=1000)
    assert [item for _, item in found.not_verified] == list(result.manual)
    assert all(unit == "program" for unit, _ in found.not_verified)


def test_a_flagged_line_v4_rejects_is_disabled_for_the_v4_run_and_listed() -> None:
    # AUTO does nothing in the v3 simulation (V3-5); a NextMove PCI does not have it (X-PLATFORM), and the
    # line would raise "Keyword not supported on this platform" when it runs.
    result = migrate("AUTO\nPRINT 5\n")
    auto = _line_of(result, "AUTO")
    assert any(item.rule == "X-PLATFORM" and item.line == auto for item in result.manual)
    found = verify(result, until_ms=100)
    assert found.disabled == (Place("program", auto),)
    assert found.verdict is Verdict.EQUIVALENT


def test_a_v3_original_its_compiler_rejects_leaves_nothing_to_compare() -> None:
    # v3 declares a variable where it is first assigned: reading b first is "Undefined Variables"
    # (001:1352-1367); the migration DIMs it, and v4 runs.
    found = verify(migrate("PRINT b\nb = 2\n"), until_ms=100)
    assert found.verdict is Verdict.INCOMPLETE
    assert found.short is not None and found.short.startswith("the v3 original does not compile: ")
    assert "Undefined Variables at line 1" in found.short
    assert found.differences == ()


def test_a_keyword_the_simulator_does_not_model_makes_the_comparison_incomplete() -> None:
    found = verify(migrate('PRINT "a"\nCOMMSON\nPRINT "b"\n'), until_ms=100)
    assert found.verdict is Verdict.INCOMPLETE
    assert found.short == "COMMSON (command) is not simulated by mint-run"


def test_the_scenario_drives_both_runs() -> None:
    # Input 0 goes high at 100 ms: both programs leave their PAUSE then, print and end.
    program = 'PAUSE IN0\nPRINT "pressed"\n'
    pressed = Scenario(inputs=(InputLevel(time_ms=100, channel=0, level=1),))
    found = verify(migrate(program), scenario=pressed, until_ms=1000)
    assert found.verdict is Verdict.EQUIVALENT
    assert found.compared_ms == 100
    assert (found.v3_stop.reason, found.v3_stop.time_ms) == ("end", 100)
    unpressed = verify(migrate(program), until_ms=1000)
    assert (unpressed.v3_stop.reason, unpressed.v4_stop.reason) == ("deadlock", "deadlock")


def _migration(v3: str, v4: str, *flagged_lines: int) -> MigrationResult:
    """A migration as a rule might have made it, with a manual item on each of ``flagged_lines``."""
    manual = tuple(ManualItem("X-TEST", line, "left for a person", line) for line in flagged_lines)
    return MigrationResult(v3, v4, (), manual, {})


def test_a_flagged_line_whose_removal_breaks_its_block_is_kept_and_the_comparison_waits_for_it() -> None:
    # zz is not declared in v4: line 1 is in error, but without it ENDIF (line 2) would have no IF
    found = verify(_migration("LOOP\nENDL\n", "IF zz DO\nENDIF\nLOOP\nENDL\n", 1), until_ms=100)
    assert found.disabled == ()
    assert found.verdict is Verdict.INCOMPLETE
    assert found.short is not None
    assert found.short.startswith("the v4 program does not compile until program line 1, left for a person, is done")
    assert found.compared_ms == 0  # the v3 run went on, but there was nothing to compare it with


def test_a_line_in_error_nobody_flagged_is_a_divergence_at_the_start() -> None:
    found = verify(_migration('PRINT "x"\n', 'PRINT "x"\nLOOP\n'), until_ms=100)
    assert found.verdict is Verdict.DIVERGES
    assert found.divergence is not None
    assert (found.divergence.time_ms, found.divergence.what) == (0, "stop")
    assert found.divergence.v4_line == Place("program", 2)
    assert found.divergence.v3 == "end at 0 ms"


def test_output_cut_off_at_the_horizon_is_not_a_divergence() -> None:
    # The migration adds AXES and DIM key before the loop, so at the end of some milliseconds the v4 run is
    # a line behind; the runs cut there at --until-ms would print it next. Every horizon must compare equal.
    result = migrate('LOOP\n  ?"A .. Start"\n  key = INKEY\nENDL\n')
    verdicts = {until: verify(result, until_ms=until).verdict for until in range(1, 31)}
    assert set(verdicts.values()) == {Verdict.EQUIVALENT}, verdicts


def test_output_a_run_that_ended_never_printed_is_a_divergence_even_at_the_horizon() -> None:
    # the v4 text prints one line more before its END: the v3 run is over, so that line cannot come later
    result = migrate('PRINT "a"\n')
    altered = replace(result, text=result.text + 'PRINT "b"\n')
    divergence = verify(altered, until_ms=100).divergence
    assert divergence is not None
    assert (divergence.what, divergence.v3, divergence.v4) == ("terminal", "(nothing more)", "'b'")


def test_output_a_run_that_ended_after_the_horizon_prints_late_is_no_divergence() -> None:
    # A slice runs 20 statements a ms: v3 prints at 0 ms (statement 20) and is cut short at 1 ms by COMMSON,
    # which the simulator does not model, so the horizon is 0 ms. The v4 text has DIM a in front, prints at
    # 1 ms and ends there: a ms late, not missing, and the comparison is incomplete, not divergent.
    found = verify(migrate("a = 1\n" * 19 + 'PRINT "b"\nCOMMSON\n'), until_ms=100)
    assert (found.verdict, found.divergence) == (Verdict.INCOMPLETE, None)
    assert found.short == "COMMSON (command) is not simulated by mint-run"


def test_a_move_a_slice_earlier_cut_off_mid_move_at_any_horizon_is_equivalent() -> None:
    # A slice runs 20 statements a ms: without 20 of the v3 program's assignments the v4 move starts a
    # ms earlier, inside the 2 ms tube. Cut off while it cruises at 20 counts/ms, the runs' last samples
    # have no later ones to match, which must not count as a divergence.
    program = "SPEED = 20000 : ACCEL = 100000\n" + "a = 1\n" * 40 + "MOVER.0 = 100000 : GO.0\nPAUSE IDLE.0\n"
    result = migrate(program)
    earlier = replace(result, text=result.text.replace("a = 1\n" * 20, "", 1))
    verdicts = {until: verify(earlier, scenario=DRIVES, until_ms=until).verdict for until in range(295, 306)}
    assert set(verdicts.values()) == {Verdict.EQUIVALENT}, verdicts


def test_errors_a_slice_apart_match_at_every_horizon() -> None:
    # v3 runs 40 assignments in the slices of 0 and 1 ms and fails on RETURN w/o GOSUB at 2 ms; the v4 text
    # without 20 of them (and with AXES and DIM a) fails at 1 ms. Cut off at 1 ms, the v3 run has not yet
    # met its error; that is not a divergence either.
    result = migrate("a = 1\n" * 40 + "RETURN\n")
    earlier = replace(result, text=result.text.replace("a = 1\n" * 20, "", 1))
    found = {until: verify(earlier, until_ms=until) for until in range(5)}
    assert {until: verification.verdict for until, verification in found.items()} == dict.fromkeys(
        range(5), Verdict.EQUIVALENT
    )
    assert (found[4].v3_stop.reason, found[4].v3_stop.time_ms) == ("error", 2)
    assert (found[4].v4_stop.reason, found[4].v4_stop.time_ms) == ("error", 1)


def test_a_run_that_goes_on_where_the_original_ended_diverges_when_the_original_ends() -> None:
    # the v4 text loops for ever after its PRINT, silently: nothing it prints or moves differs, but v3 ended
    result = migrate('PRINT "a"\n')
    altered = replace(result, text=result.text + "LOOP\nENDL\n")
    found = verify(altered, until_ms=100)
    assert found.verdict is Verdict.DIVERGES
    divergence = found.divergence
    assert divergence is not None
    assert (divergence.time_ms, divergence.what, divergence.v3, divergence.v4) == (0, "stop", "end at 0 ms", "runs on")


def test_a_v4_program_ending_while_v3_waits_in_go_is_no_difference_by_itself() -> None:
    # v3's second GO waits until the first 10000-count move ends, about 700 ms in (200 ms up to speed,
    # 300 at it, 200 down), then its program ends; v4's ends in the first ms. The moves are the same, so
    # at every horizon, before v3 ends or after, the runs are equivalent.
    program = "SPEED = 20000 : ACCEL = 100000\nMOVER.0 = 10000 : GO.0\nMOVER.0 = 10000 : GO.0\n"
    result = migrate(program)
    for until in (100, 400, 700, 2000):
        found = verify(result, scenario=DRIVES, until_ms=until)
        assert found.verdict is Verdict.EQUIVALENT, (until, found.divergence)
    assert 700 <= found.v3_stop.time_ms <= 704 and found.v4_stop.time_ms == 0


def test_two_runs_that_both_fail_at_once_verify_nothing() -> None:
    # Without --drives enabled both drives start disabled: v3 and v4 stop on the first move at 0 ms. That
    # they agree says nothing of the migration (a new user's trial read "equivalent over 0 ms").
    found = verify(migrate(PRINTS_AND_MOVES), until_ms=5000)
    assert found.verdict is Verdict.INCOMPLETE
    assert (found.v3_stop.reason, found.v4_stop.reason, found.compared_ms) == ("error", "error", 0)
    assert found.short is not None and found.short.startswith("both runs stopped on an error at 0 ms (")


def test_two_errors_at_once_on_different_statements_diverge() -> None:
    """v3's ACCEL takes 1000.0 to 8388607.0 (v3 guide 001:5649), so ``ACCEL = 100`` stops the v3 run at line 2
    after the 10 ms WAIT; v4 takes 0.0 < x (000:6143-6167) and runs it, then its move on a drive never
    enabled stops on error 40 (000:2711-2713) in the same millisecond. Two errors at once, on two statements:
    the migration ran a line the original failed on (a new user's trial read "equivalent over 2 ms")."""
    program = "WAIT = 10\nACCEL = 100\nMOVER.0 = 50 : GO.0\n"
    result = migrate(program)
    found = verify(result, until_ms=100)
    assert found.verdict is Verdict.DIVERGES
    assert (found.v3_stop.reason, found.v3_stop.time_ms, found.v3_stop.line) == ("error", 10, Place("program", 2))
    assert (found.v4_stop.reason, found.v4_stop.time_ms) == ("error", 10)
    divergence = found.divergence
    assert divergence is not None
    assert (divergence.time_ms, divergence.what, divergence.timing_only) == (10, "stop", False)
    assert divergence.v3_line == Place("program", 2)
    assert divergence.v4_line == Place("program", _line_of(result, "MOVER.0 = 50"))


def test_two_errors_at_once_on_the_same_statement_agree() -> None:
    """With ACCEL in both ranges, both runs stop on the move of line 3 after the WAIT: v3 on its servo left
    off, v4 on error 40 (000:2711-2713); the messages differ by dialect (X-PRINT), the statement is one."""
    found = verify(migrate("WAIT = 10\nACCEL = 1000\nMOVER.0 = 50 : GO.0\n"), until_ms=100)
    assert found.verdict is Verdict.EQUIVALENT
    assert found.v3_stop.line == Place("program", 3)
    assert (found.v3_stop.time_ms, found.v4_stop.time_ms) == (10, 10)
