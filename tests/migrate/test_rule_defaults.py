"""S-DEFAULTS reports the changed v3 defaults a program relies on; S-DEFAULTS-V3 (opt-in) writes them."""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate
from tests.migrate.helpers import one_rule, rewritten

MOVES = "REM demo\nAXES[0,1]\nMOVEA = 10,20 : GO\nPAUSE IDLE[0,1]\n"


def _notes(source: str, **options: str) -> list[str]:
    return [item.reason for item in one_rule("S-DEFAULTS", source, **options).manual if item.rule == "S-DEFAULTS"]


def test_each_default_relied_on_is_reported_with_the_v4_statement() -> None:
    assert _notes(MOVES) == [
        "FOLERRORFATAL[0,1] = 16000; : REM v3 default 16000, v4 1000 (--with S-DEFAULTS-V3 writes it)",
        "IDLEPOS[0,1] = 16000; : REM v3 default 16000, v4 1000 (--with S-DEFAULTS-V3 writes it)",
        "SPEED[0,1] = <value>; : REM v3 default 40000 (80000 in the CONFIG table), v4 20000",
        "ACCEL[0,1] = <value>; : DECEL[0,1] = <value>; : REM v3 default 300000 (3000000 in the CONFIG table),"
        " v4 300000",
    ]


def test_the_notes_go_after_the_header_and_keep_every_line() -> None:
    text = rewritten("S-DEFAULTS", MOVES)
    lines = text.splitlines()
    assert lines[0] == "REM demo" and lines[1].startswith("REM MIGRATE: S-DEFAULTS: FOLERRORFATAL")
    assert [line for line in lines if not line.startswith("REM MIGRATE:")] == MOVES.splitlines()


def test_a_parameter_the_program_writes_is_not_reported() -> None:
    source = "MFOLERR = 50;\nIDLE = 5;\nSPEED = 100;\nACCEL = 1000;\nHMSPEED = 10;\nHOME = 0\nMOVEA = 1 : GO\n"
    assert _notes(source) == []


def test_a_parameter_written_on_other_axes_is_still_reported_for_the_axis_that_moves() -> None:
    # SPEED.1 leaves axis 0 at its default: v3 40000 (v3:11797) or 80000 (v3:6943), v4 20000 (v4:16169)
    speed = "SPEED[0] = <value>; : REM v3 default 40000 (80000 in the CONFIG table), v4 20000"
    assert speed in _notes("SP.1 = 30\nMA.0 = 10 : GO.0\n")
    assert speed in _notes("MA.0 = 10 : GO.0\n")
    assert not any(note.startswith("SPEED") for note in _notes("SP.0 = 30\nMA.0 = 10 : GO.0\n"))


def test_a_program_that_does_not_move_relies_on_nothing() -> None:
    assert _notes("x = 1\nPRINT x\n") == []
    assert rewritten("S-DEFAULTS", "x = 1\n") == "x = 1\n"


def test_home_relies_on_the_home_speed_of_its_axes_only() -> None:
    notes = _notes("AXES[0,1]\nHOME.1 = 0\nJOG.0 = 5\n")
    assert "HOMESPEED[1] = <value>; : REM v3 default 40000 (20000 in the CONFIG table), v4 40000" in notes
    assert notes[0].startswith("FOLERRORFATAL[0,1] = 16000;")


def test_stepper_axes_are_left_out() -> None:
    notes = _notes("AXES[0,1]\nCONFIG = _servo, _stepper\nMOVEA = 1,2 : GO\n")
    assert notes[0].startswith("FOLERRORFATAL[0] = 16000;")


def test_computed_axes_fall_back_to_every_axis_of_the_controller() -> None:
    notes = _notes("MOVEA[a] = 1 : GO[a]\n", controller="mintdrive")
    assert notes[0].startswith("FOLERRORFATAL[0] = 16000;")


def test_the_notes_go_into_the_configuration_file() -> None:
    result = one_rule("S-DEFAULTS", "MOVEA = 1 : GO\n", config="AUTO\nSCALE = 10\n")
    assert result.text == "MOVEA = 1 : GO\n"
    assert result.configuration is not None
    assert result.configuration.text.splitlines()[1].startswith("REM MIGRATE: S-DEFAULTS: FOLERRORFATAL[0] = 16000;")
    assert result.configuration.text.endswith("SCALE = 10\n")


def test_opt_in_writes_the_v3_values_and_only_reports_those_the_v3_manual_gives_twice() -> None:
    # SPEED, ACCEL and HMSPEED have one default in their v3 keyword entries and another in the CONFIG table
    result = migrate(MOVES, only=["S-DEFAULTS", "S-DEFAULTS-V3"])
    assert result.text == (
        "REM demo\n"
        "REM MIGRATE: S-DEFAULTS: SPEED[0,1] = <value>; : REM v3 default 40000 (80000 in the CONFIG table), v4 20000\n"
        "REM MIGRATE: S-DEFAULTS: ACCEL[0,1] = <value>; : DECEL[0,1] = <value>; : REM v3 default 300000"
        " (3000000 in the CONFIG table), v4 300000\n"
        "FOLERRORFATAL[0,1] = 16000;\nIDLEPOS[0,1] = 16000;\n"
        "AXES[0,1]\nMOVEA = 10,20 : GO\nPAUSE IDLE[0,1]\n"
    )
    assert {change.rule for change in result.changes} == {"S-DEFAULTS-V3"}


def test_the_insertion_is_not_on_by_default() -> None:
    assert "FOLERRORFATAL[0,1] = 16000;\n" not in migrate(MOVES).text
    assert "\nFOLERRORFATAL[0,1] = 16000;\n" in migrate(MOVES, opt_in=["S-DEFAULTS-V3"]).text


def test_both_are_idempotent_also_with_every_other_rule() -> None:
    for rules in (["S-DEFAULTS"], ["S-DEFAULTS", "S-DEFAULTS-V3"]):
        once = migrate(MOVES, only=rules).text
        assert migrate(once, only=rules).text == once
    full = migrate(MOVES, opt_in=["S-DEFAULTS-V3"]).text
    assert migrate(full, opt_in=["S-DEFAULTS-V3"]).text == full


SPEED_NOTE = "SPEED[0] = <value>; : REM v3 default 40000 (80000 in the CONFIG table), v4 20000"


@pytest.mark.parametrize(
    ("write", "reported"),
    [
        # zero is false, any other value true (v3:2009); IF .. THEN runs its statements when true (v3:2101)
        pytest.param("IF 1 THEN SPEED = 4\n", False, id="if-then-always-runs"),
        pytest.param("IF 0 THEN SPEED = 4\n", True, id="if-then-never-runs"),
        pytest.param("IF IN1 THEN SPEED = 4\n", False, id="if-then-on-an-input-may-run"),
        # an IF block runs the part before ELSE when true, after it when false (v3:2134)
        pytest.param("IF 0 DO\n  SPEED = 4\nENDIF\n", True, id="if-block-never-runs"),
        pytest.param("IF 1 DO\n  x = 1\nELSE\n  SPEED = 4\nENDIF\n", True, id="else-of-a-true-block-never-runs"),
        pytest.param("IF 0 DO\n  x = 1\nELSE\n  SPEED = 4\nENDIF\n", False, id="else-of-a-false-block-runs"),
    ],
)
def test_a_write_that_never_runs_leaves_the_default_relied_on(write: str, reported: bool) -> None:
    # S-DEFAULTS covers programs that never write the parameter (spec S-DEFAULTS)
    assert (SPEED_NOTE in _notes(write + "MOVEA = 10 : GO\n")) is reported


@pytest.mark.parametrize(
    ("source", "keyword"),
    [
        pytest.param("MFOLERR = 100;\nMFOLERR.1 = 50\nMOVEA = 1,1 : GO\n", "FOLERRORFATAL", id="mfolerr"),
        pytest.param("HMSPEED = 10;\nHMSPEED.1 = 20\nHOME = 0,0\n", "HOMESPEED", id="hmspeed"),
        pytest.param("HS = 10;\nHS.1 = 20\nHOME = 0,0\n", "HOMESPEED", id="hs-abbreviation"),
    ],
)
def test_a_renamed_fill_beside_a_write_on_one_axis_still_sets_every_axis(source: str, keyword: str) -> None:
    # 'MFOLERR = 100;' sets every default axis (the ';' fill, v3:1109), axes 0 and 1 of AXES[0,1,2]
    # (v3:1029-1033) that MOVEA = 1,1 and HOME = 0,0 use; once renamed, the v3 reader cannot place the
    # fill on its axes, but the write on axis 1 beside it must not make axis 0 look unset
    result = migrate(source, opt_in=["S-DEFAULTS-V3"])
    assert not any(item.reason.startswith(keyword) for item in result.manual if item.rule == "S-DEFAULTS")
    assert f"{keyword}[0] = 16000;" not in result.text
