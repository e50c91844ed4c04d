"""S-PROLOGUE: the I/O assignments v3 hardware made, as commented v4 statements to fill in."""

from __future__ import annotations

import mintlang
from mintlang.diagnostics import Severity
from mintlang.migrate import migrate
from tests.migrate.helpers import one_rule, rewritten


def _notes(source: str, **options: str) -> list[str]:
    return [item.reason for item in one_rule("S-PROLOGUE", source, **options).manual if item.rule == "S-PROLOGUE"]


def test_moves_need_the_drive_enable_the_limits_and_the_stop_input() -> None:
    assert _notes("AXES[0,1]\nMOVEA = 1,2 : GO\n") == [
        "DRIVEENABLEOUTPUT[0,1] = <output>; : REM v3 amplifier enable was dedicated; -1 if none is wired",
        "DRIVEENABLE[0,1] = 1; : REM before the first move (after CONFIG); v4 error 40 otherwise",
        "LIMITFORWARDINPUT[0,1] = <input>; : REM v3 had one limit input per axis for both directions",
        "LIMITREVERSEINPUT[0,1] = <input>; : REM the same input as forward if wired as in v3",
        "STOPINPUT[0,1] = <input>; : REM v3 had a stop input",
    ]


def test_home_and_stop_need_their_inputs() -> None:
    notes = _notes("HOME.1 = 0\n#STOP\nRETURN\n")
    assert "HOMEINPUT[1] = <input>; : REM v3 home input was dedicated" in notes
    assert "STOPINPUT[1] = <input>; : REM v3 had a stop input" in notes
    assert _notes("#STOP\nRETURN\n", controller="mintdrive") == ["STOPINPUT[0] = <input>; : REM v3 had a stop input"]


def test_what_the_program_already_assigns_is_not_listed() -> None:
    source = "DRIVEENABLEOUTPUT.0 = 3\nRESET.0\nLIMITFORWARDINPUT.0 = 1\nLIMITREVERSEINPUT.0 = 1\nJOG.0 = 5\n"
    assert _notes(source) == []


def test_nothing_without_motion() -> None:
    assert rewritten("S-PROLOGUE", "x = 1\nPRINT x\n") == "x = 1\nPRINT x\n"


def test_the_output_still_compiles_and_is_idempotent() -> None:
    source = "REM header\nAXES[0,1]\nMOVEA = 1,2 : GO\n"
    once = rewritten("S-PROLOGUE", source)
    assert once.startswith("REM header\nREM MIGRATE: S-PROLOGUE: DRIVEENABLEOUTPUT[0,1] = <output>;")
    assert [line for line in once.splitlines() if "REM MIGRATE" not in line] == source.splitlines()
    assert not [d for d in mintlang.parse(once, "v4").diagnostics if d.severity is Severity.ERROR]
    assert rewritten("S-PROLOGUE", once) == once


def test_the_notes_go_into_the_configuration_file() -> None:
    result = one_rule("S-PROLOGUE", "MOVEA = 1 : GO\n", config="AUTO\n")
    assert result.configuration is not None
    assert result.configuration.text.startswith("AUTO\nREM MIGRATE: S-PROLOGUE: DRIVEENABLEOUTPUT[0] = <output>;")


def test_limit_switches_read_without_moves_still_need_their_inputs() -> None:
    notes = rewritten("S-PROLOGUE", "AXES[0,1]\nPAUSE LIMIT.0 = 0 & LIMIT.1 = 0\n")
    assert "LIMITFORWARDINPUT[0,1] = <input>;" in notes and "LIMITREVERSEINPUT[0,1] = <input>;" in notes


def _home_notes(source: str) -> list[str]:
    """The HOMEINPUT note of a whole migration: S-READ writes a read of HOME as HOMESWITCH first."""
    return [item.reason for item in migrate(source).manual if item.rule == "S-PROLOGUE" and "HOMEINPUT" in item.reason]


def test_a_bare_home_read_needs_the_input_of_the_first_default_axis_only() -> None:
    # reading HOME gives the home switch (v3:3509); without an axis it reads the first axis of AXES (v3:1127),
    # which before any AXES statement is axis 0 (the power-up AXES starts at 0, v3:1029)
    assert _home_notes('IF HOME THEN PRINT "homed"\n') == ["HOMEINPUT[0] = <input>; : REM v3 home input was dedicated"]
    assert _home_notes("AXES[1,2]\nIF HOME THEN PRINT 1\n") == [
        "HOMEINPUT[1] = <input>; : REM v3 home input was dedicated"
    ]


def test_a_home_switch_read_adds_its_axis_to_those_homed() -> None:
    assert _home_notes("HOME.1 = 0\nIF HOME THEN PRINT 1\n") == [
        "HOMEINPUT[0,1] = <input>; : REM v3 home input was dedicated"
    ]
