"""Every v3 program of the corpus, migrated and verified: the verdict each must give, and why.

Each program of ``tests/corpus/v3/programs`` (with its configuration file, and
the configuration files that have no program) is migrated for the NextMove PCI
and verified against its original on the EuroServo, with the drives enabled, for
at most 1000 simulated ms. Most of the guide's listings are fragments (a routine
alone, variables set elsewhere) that the v3 compiler refuses or that stop on an
error (runtime/BEHAVIOUR.md, "The guide's programs"); the table says, for every
program, what the comparison finds and why. A program whose verdict changes
fails here: a migration that became equivalent should have its row moved, one
that stopped being equivalent is a regression.
"""

from __future__ import annotations

from dataclasses import dataclass

import pytest

from mintlang.migrate import migrate
from mintlang.migrate.verification import Verdict, Verification, verify
from mintlang.runtime.scenario import DrivesEnabled, InputLevel, Scenario
from tests.corpus_files import CORPUS

PROGRAMS = CORPUS / "v3" / "programs"
UNTIL_MS = 1000
DRIVES = Scenario(drives=(DrivesEnabled(),))
# input 1 toggles every 10 ms: the teach-in loops (PAUSE IN1) record a point at each press
TEACHING = Scenario(
    drives=(DrivesEnabled(),), inputs=tuple(InputLevel(time_ms=10 * k, channel=1, level=k % 2) for k in range(1, 60))
)


@dataclass(frozen=True)
class Expected:
    """The verdict, and what the report must say: part of the reason an incomplete comparison gives,
    or the channel and part of a side of the first divergence."""

    verdict: Verdict
    says: str = ""
    scenario: Scenario = DRIVES


def equivalent(scenario: Scenario = DRIVES) -> Expected:
    return Expected(Verdict.EQUIVALENT, scenario=scenario)


HANDLER_ALONE = "both runs stopped on an error at 0 ms (ERROR: Program: RETURN w/o GOSUB at line "
V3_REFUSES = "the v3 original does not compile: "  # fragments: BEHAVIOUR.md's table of the guide's programs

EXPECTED: dict[str, Expected] = {
    # Equivalent: the migration does what the original does over the whole comparison.
    "char.mnt": equivalent(),  # a menu polled with INKEY for the whole second
    "correct.mnt": equivalent(),
    "l01564_teach_by_hand.mnt": Expected(
        # a fragment: y_position is an array of an earlier example; v3 stops on it at the first press,
        # the migration flags it (M-DIM) and its line is disabled for the v4 run
        Verdict.DIVERGES,
        "stop at 10 ms: v3 error at 10 ms: ERROR: Program: Invalid Index at line 9",
        TEACHING,
    ),
    "l01588_offline_arrays.mnt": equivalent(TEACHING),
    "l01625_insertion.mnt": equivalent(),
    "l01938_load_array_data.mnt": equivalent(),  # its LOAD line is flagged (X-HOST) and disabled for the v4 run
    "l02981_inkey_input.mnt": equivalent(),
    "l03246_offset_indexing.mnt": equivalent(),
    "l03444_contouring.mnt": equivalent(),
    "l04492_io_on_the_fly.mnt": equivalent(),  # v3's GO ends the program at 40 ms, v4's at 0: the moves are the same
    "l06141_onerror_beep.mnt": equivalent(),
    "l07617_encoder_correction.mnt": equivalent(),
    "l08546_gosub_init.mnt": equivalent(),
    "l09798_load_in_program.mnt": equivalent(),  # LOAD flagged (X-HOST) and disabled for the v4 run
    "l11549_save_in_program.mnt": equivalent(),  # SAVE likewise
    "nonvol1.mnt": equivalent(),
    "3axis.cfg": equivalent(),  # its AUTO is flagged (X-PLATFORM) and disabled for the v4 run
    "l06116_baud.cfg": equivalent(),  # AUTO (X-PLATFORM) and BAUD (S-BAUD) likewise
    # Diverges: known v3/v4 differences, or fragments that end differently.
    "intro.mnt": Expected(
        # v3 homes on its dedicated home inputs (V3-8); v4 homes on the input HOMEINPUT names, a statement
        # the S-PROLOGUE note leaves for a person to fill in, and without it HOME is error 5
        Verdict.DIVERGES,
        "stop at 1 ms: v3 runs on / v4 error at 1 ms: R0005: PROGRAM No digital input assigned",
    ),
    "l02443_draw_b.mnt": Expected(
        # a routine shown alone ends on RETURN w/o GOSUB: at 30 ms in v4, at 80 ms in v3, whose GO waits for
        # the move ahead (V3-10). X-GO-TIMING flags what such a GO delays, but not a RETURN
        Verdict.DIVERGES,
        "stop at 30 ms: v3 runs on / v4 error at 30 ms: R2010: PROGRAM RETURN w/o GOSUB",
    ),
    "l03033_comms_commands.mnt": Expected(
        # the guide's misprint COMMON (for COMMSON): an invalid command v3 stops on; flagged (X-COMMENTED) and
        # disabled for the v4 run, which goes on
        Verdict.DIVERGES,
        "stop at 0 ms: v3 error at 0 ms: ERROR: Program: Invalid Command at line 4 (COMMON) / v4 runs on",
    ),
    # #ONERROR handlers shown alone, run from their first line: their RETURN is "RETURN w/o GOSUB", which v3
    # cannot trap and ends on (001:4916, V3-6); v4 calls #ONERROR for it (the handler X-ONERROR flags), and
    # as it is an interpreter error the RETURN from there ends the program on it (000:4614-4619): both runs
    # stop on the error at once, with nothing compared
    "l04587_onerror_limit_servoff.mnt": Expected(Verdict.INCOMPLETE, HANDLER_ALONE),
    "l06591_onerror_cancel.mnt": Expected(Verdict.INCOMPLETE, HANDLER_ALONE),
    "l07458_onerror_dislimit.mnt": Expected(Verdict.INCOMPLETE, HANDLER_ALONE),
    "l07823_onerror_error_limit.mnt": Expected(Verdict.INCOMPLETE, HANDLER_ALONE),
    "l09710_onerror_limit.mnt": Expected(Verdict.INCOMPLETE, HANDLER_ALONE),
    # Incomplete: the v3 compiler refuses the listing (a fragment, or one of the guide's misprints).
    "l02139_if_block.mnt": Expected(Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Program: Undefined Variables"),
    "l02165_if_nested.mnt": Expected(Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Program: Undefined Variables"),
    "l02594_feed_to_length.mnt": Expected(Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Program: Undefined Variables"),
    "l02849_keypad_menu.mnt": Expected(Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Program: Invalid label"),
    "l03020_comms_jog_between.mnt": Expected(Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Program: Undefined Variables"),
    "l03514_two_datums.mnt": Expected(Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Program: Undefined Variables"),
    "l03721_clutch_distance.mnt": Expected(Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Program: Undefined Variables"),
    "l03783_software_gearbox.mnt": Expected(Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Program: Undefined Variables"),
    "l04031_flying_shear_segments.mnt": Expected(
        Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Program: Undefined Variables"
    ),
    "l04266_pulse_offset.mnt": Expected(Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Program: Undefined Variables"),
    "l04942_onerror_err_codes.mnt": Expected(Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Program: ELSE/ENDIF w/o IF DO"),
    "l05191_protect.mnt": Expected(Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Program: Invalid label"),
    "l07987_fastpos_label_length.mnt": Expected(Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Program: Undefined Variables"),
    "l08234_for_next.mnt": Expected(Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Program: Undefined Variables"),
    "l08809_if_do.mnt": Expected(Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Program: Undefined Variables"),
    "l09165_inkey_menu.mnt": Expected(Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Program: Invalid label"),
    "l12265_trigger_fly.mnt": Expected(Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Program: Undefined Variables"),
    "l14055_dead_time_before.mnt": Expected(Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Program: Undefined Variables"),
    "l14068_dead_time_after.mnt": Expected(Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Program: Undefined Variables"),
    "nonvol2.mnt": Expected(Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Program: Undefined Variables"),  # V3-13
    "teach.mnt": Expected(Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Program: Syntax error at line 29"),
    # its configuration writes CURRLIMIT = 0;, outside v3's 1..100 (V3-5)
    "template.mnt": Expected(Verdict.INCOMPLETE, V3_REFUSES + "ERROR: Config: Out of range at line 18"),
    # Incomplete: the migration compiles once a person deals with a flagged line kept for the v4 run
    # (disabling it would break its block): DIR has no v4 keyword, XENCODER no expansion board.
    "l04404_joystick.mnt": Expected(Verdict.INCOMPLETE, "the v4 program does not compile until program line 48"),
    "l12707_xencoder.mnt": Expected(Verdict.INCOMPLETE, "the v4 program does not compile until program line 19"),
    # Incomplete: the v3 original stops on a keyword the simulator does not model (BEHAVIOUR.md,
    # "Not simulated in v3"), before anything differs.
    "l02496_onerror_reset_run.mnt": Expected(Verdict.INCOMPLETE, "RUN (command) is not simulated"),
    "l02999_readkey_jog.mnt": Expected(Verdict.INCOMPLETE, "READKEY (read) is not simulated"),
    "l04071_flying_shear_profile.mnt": Expected(Verdict.INCOMPLETE, "MASTERINC (write) is not simulated"),
    "l04120_flying_shear_knife.mnt": Expected(Verdict.INCOMPLETE, "FOLLOWAXIS (write) is not simulated"),
    "l04850_data_capture.mnt": Expected(Verdict.INCOMPLETE, "DATETIME (write) is not simulated"),
    "l05037_onerror_recovery.mnt": Expected(Verdict.INCOMPLETE, "ERR (read before any error"),
    "l08434_gearbox_offset.mnt": Expected(Verdict.INCOMPLETE, "FOLLOWAXIS (write) is not simulated"),
    "l13204_comms_jog.mnt": Expected(Verdict.INCOMPLETE, "COMMSON (command) is not simulated"),
    "l13252_comms_wire_winding.mnt": Expected(Verdict.INCOMPLETE, "COMMSON (command) is not simulated"),
    "l13267_comms_commands.mnt": Expected(Verdict.INCOMPLETE, "COMMSON (command) is not simulated"),
    "template_stepper.cfg": Expected(Verdict.INCOMPLETE, "CONFIG (stepper, micro-stepper and inverter axes)"),
}


def _applications() -> dict[str, tuple[str, str | None]]:
    """name -> (program, configuration) of every program, and of every configuration file without one."""
    found: dict[str, tuple[str, str | None]] = {}
    for path in sorted(PROGRAMS.glob("*.mnt")):
        configuration = path.with_suffix(".cfg")
        found[path.name] = (
            path.read_text("utf-8"),
            configuration.read_text("utf-8") if configuration.exists() else None,
        )
    for path in sorted(PROGRAMS.glob("*.cfg")):
        if not path.with_suffix(".mnt").exists():
            found[path.name] = ("", path.read_text("utf-8"))
    return found


APPLICATIONS = _applications()


def test_the_table_has_a_row_for_every_program_of_the_corpus_and_no_other() -> None:
    assert sorted(EXPECTED) == sorted(APPLICATIONS)


def _told(found: Verification) -> str:
    """What the report says that a row's ``says`` is looked for in."""
    divergence = found.divergence
    if divergence is None:
        return found.short or ""
    return f"{divergence.what} at {divergence.time_ms} ms: v3 {divergence.v3} / v4 {divergence.v4}"


@pytest.mark.parametrize("name", sorted(APPLICATIONS))
def test_every_v3_program_of_the_corpus_verifies_as_its_row_says(name: str) -> None:
    expected = EXPECTED[name]
    program, configuration = APPLICATIONS[name]
    found = verify(migrate(program, config=configuration), scenario=expected.scenario, until_ms=UNTIL_MS)
    assert found.verdict is expected.verdict, _told(found)
    assert expected.says in _told(found)
    if expected.verdict is Verdict.INCOMPLETE:
        assert found.divergence is None  # nothing differed before the comparison had to stop
