"""A file already in Mint v4 is recognised and left alone, and running the migrator on its own
output is a no-op.

Recognised (``recognise``): the rewrite rules find nothing to rewrite, and the application
shows a form only v4 has: a scalar DIM (v3's DIM declares arrays only, v3:7304), a v4-only
keyword, or a note mint-migrate wrote. A program without either reads the same in both
versions and cannot be told from a v3 original that needs no rewrite: it keeps getting its
notes, which is the safe side. (A v4 program the rules would rewrite: see
``test_hand_ported_v4_is_left_alone``.)
"""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.migrate import migrate
from mintlang.migrate.cli import migrate as command
from tests.migrate.golden import Case, cases

CASES = cases()

# Reviewed by hand: after the migration these use no variable and no v4-only keyword (AXES,
# JOG, LOAD, TIME, COMMS, PRINT read the same in both versions).
NO_V4_FORM = {
    "l01938_load_array_data",
    "l03020_comms_jog_between",
    "l04492_io_on_the_fly",
    "l04850_data_capture",
    "l05191_protect",
    "l06116_baud",
    "l06141_onerror_beep",
    "l09798_load_in_program",
    "l11549_save_in_program",
}


def _without_markers(text: str | None) -> str | None:
    if text is None:
        return None
    return "".join(line for line in text.splitlines(keepends=True) if "REM MIGRATE:" not in line)


def _expected(case: Case) -> tuple[str, str | None]:
    return case.read("expected.mnt") or "", case.read("expected.cfg")


@pytest.mark.parametrize("case", CASES, ids=lambda case: case.name)
def test_check_passes_on_the_migrators_own_output(case: Case) -> None:
    """``--check`` on what ``--write`` wrote: nothing left to rewrite, exit 0."""
    arguments = ["--check", "--format", "json"]
    if (case.folder / "expected.cfg").exists():
        arguments += ["--config", str(case.folder / "expected.cfg")]
    if (case.folder / "expected.mnt").exists():
        arguments.append(str(case.folder / "expected.mnt"))
    result = CliRunner().invoke(command, arguments)
    assert result.exit_code == 0, result.output
    assert '"changes": 0' in result.output


@pytest.mark.parametrize("case", [case for case in CASES if case.name not in NO_V4_FORM], ids=lambda case: case.name)
def test_a_migrated_file_whose_markers_were_removed_is_left_alone(case: Case) -> None:
    program, config = (_without_markers(text) for text in _expected(case))
    result = migrate(program or "", config=config)
    assert result.already_v4
    assert result.text == program and not result.changes and not result.manual
    if config is not None:
        assert result.configuration is not None and result.configuration.text == config


@pytest.mark.parametrize("case", [case for case in CASES if case.name in NO_V4_FORM], ids=lambda case: case.name)
def test_a_file_that_reads_the_same_in_both_versions_gets_its_notes_back(case: Case) -> None:
    program, config = _expected(case)
    result = migrate(_without_markers(program) or "", config=_without_markers(config))
    assert not result.already_v4
    assert result.text == program  # the very markers removed, and nothing else
    if config is not None:
        assert result.configuration is not None and result.configuration.text == config


def test_the_issue_example_nine_notes_are_not_added_back(tmp_path: Path) -> None:
    """The report that started this: a program migrated, its REM MIGRATE lines dealt with and
    removed; a new run added its nine prologue notes back, "changed" with 0 changes."""
    case = next(case for case in CASES if case.name == "l03033_comms_commands")
    program = _without_markers(case.read("expected.mnt")) or ""
    path = tmp_path / "comms.mnt"
    path.write_text(program)
    result = CliRunner().invoke(command, ["--check", str(path)])
    assert result.exit_code == 0
    assert "already v4" in result.output and "1 file: 0 changed, 0 unchanged, 1 already v4; 0 changes" in result.output
    assert path.read_text() == program


def test_a_program_written_in_v4_is_left_alone() -> None:
    program = "DIM speed\nspeed = 10\nHOMESPEED.0 = speed\nMOVEA = 10 : GO\n"
    result = migrate(program, controller="mintdrive")
    assert result.already_v4 and result.text == program  # no S-PROLOGUE notes for its move


def test_a_v3_program_with_nothing_to_rewrite_keeps_its_notes() -> None:
    result = migrate("AXES[0,1]\nMOVEA = 10,20 : GO\n")
    assert not result.already_v4
    assert any(item.rule == "S-PROLOGUE" for item in result.manual)


def test_a_v4_form_beside_v3_code_does_not_stop_the_migration() -> None:
    result = migrate("DIM a\nHMSPEED = 10\n", controller="mintdrive")
    assert not result.already_v4 and "HOMESPEED = 10" in result.text


def test_a_marked_file_whose_v4_keyword_looks_like_a_v3_variable_is_its_output() -> None:
    """v3's GAIN is v4's KPROP (v4:10944-10945; its units changed: X-UNITS marks the line). Assigned and read as a
    plain name, ``kprop`` is also what a v3 variable of that name looks like, but the migration renames
    such a variable (M-IDENT): in a file it marked, the name is the keyword, and a second run keeps it."""
    first = migrate("gain = 10 : PRINT gain\n")
    assert first.text == (
        "REM MIGRATE: X-UNITS: servo gains changed units and loop rate in v4: re-tune\nkprop = 10 : PRINT kprop\n"
    )
    second = migrate(first.text)
    assert second.already_v4 and second.text == first.text


def test_a_file_marked_by_some_rules_only_is_still_migrated() -> None:
    """A run of some rules (``--only``) marks a file that still holds v3 (``GN``, v3's GAIN, is no v4
    word): Mint v4's check finds it, and the full run renames the v3 variable ``kprop`` after all."""
    staged = migrate("kprop = 5 : PRINT kprop\nGN = 10\n", only=["X-UNITS"])
    full = migrate(staged.text)
    assert not full.already_v4
    assert "kprop_u = 5 : PRINT kprop_u\n" in full.text and "KPROP = 10\n" in full.text


def test_a_file_marked_by_a_run_that_skipped_a_rule_is_still_migrated() -> None:
    """``SIN(30)`` reads alike in both versions, but v3's is a thousand times v4's (v3:2063-2081): the full
    run must scale it though the skipped run marked the file and Mint v4 finds no error in it."""
    staged = migrate("gain = 10\nPRINT SIN(30)\n", skip=["M-TRIG"])
    full = migrate(staged.text)
    assert not full.already_v4 and "(SIN(30) * 1000)" in full.text
