"""The result is valid Mint v4 on the target controller except on flagged lines: what no rule can
rewrite, such as the axes a one-axis controller lacks, gets an X-CHECK marker, and a line that
was already an error in Mint v3 an X-COMMENTED one (spec §1 step 8, X-COMMENTED)."""

from __future__ import annotations

import pytest

import mintlang
from mintlang.diagnostics import LineIndex, Severity
from mintlang.migrate import migrate
from tests.migrate.helpers import errors_left_unflagged, flagged

ONE_AXIS = ("mintdrive", "servonode51")


@pytest.mark.parametrize("controller", ONE_AXIS)
def test_axes_a_one_axis_controller_lacks_are_flagged(controller: str) -> None:
    config = "AUTO\nRESET\nCONFIG = _servo,_servo,_servo\n"
    result = migrate("MOVEA = 10,20,30 : GO\nPAUSE IDLE[0,1,2]\n", config=config, controller=controller)
    assert result.configuration is not None
    title = "MintDrive" if controller == "mintdrive" else "ServoNode 51"
    assert [(item.rule, item.line, item.reason) for item in result.manual] == [
        ("X-CHECK", 2, f"not valid Mint v4 on {title}: E2017 Too many parameters: 3 values for 1 axis"),
        ("X-CHECK", 4, f"not valid Mint v4 on {title}: E2017 Too many parameters: 3 axes listed, {title} has 1"),
    ]
    assert next((item.rule, item.line) for item in result.configuration.manual) == ("X-CHECK", 4)
    assert errors_left_unflagged(result, controller) == []


def test_a_line_already_flagged_gets_no_second_marker() -> None:
    result = migrate("x = 1\nIF MODE.1 > 2 THEN x = 2\nSTOP.1\n", controller="mintdrive")
    assert [(item.rule, item.line) for item in result.manual] == [("S-MODE", 4), ("X-CHECK", 6)]  # below DIM x
    again = migrate(result.text, controller="mintdrive")
    assert again.text == result.text
    assert [(item.rule, item.line) for item in again.manual] == [(item.rule, item.line) for item in result.manual]


def test_prologue_notes_list_only_the_axes_the_target_has() -> None:
    """The statements in the S-PROLOGUE and S-DEFAULTS notes are to be filled in and written:
    for axes a MintDrive lacks they would be error 2017 themselves."""
    result = migrate("MOVEA = 10,20,30 : GO\nPAUSE IDLE[0,1,2]\n", controller="mintdrive")
    notes = [item.reason for item in result.manual if item.rule in ("S-PROLOGUE", "S-DEFAULTS")]
    assert notes and all("[0]" in note and "[0," not in note for note in notes)
    written = migrate("MOVEA = 10,20,30 : GO\n", controller="mintdrive", opt_in=["S-DEFAULTS-V3"])
    assert "FOLERRORFATAL[0] = 16000;" in written.text


# The v3 guide's own error examples (v3:7345-7350), and a misprint the parser stops at.
INVALID_V3 = "DIM myData(x)\nDIM myData2( 3 ) = a,a+1,b+2\nPRINT 1 BEEP\n"


def test_lines_mint_check_v3_rejects_are_reported_as_invalid_in_v3() -> None:
    assert flagged("X-COMMENTED", INVALID_V3) == [
        "not valid Mint v3 either (Syntax error: the size of myData must be a number, not an expression)",
        "not valid Mint v3 either (Syntax error: the values of myData2 must be numbers, not expressions)",
        "not valid Mint v3 either (Syntax error: unexpected 'BEEP')",
    ]


def test_every_line_mint_check_v3_rejects_is_flagged() -> None:
    errors = mintlang.check_application(INVALID_V3, dialect="v3").program
    rejected = {LineIndex(INVALID_V3).position(d.span.start).line for d in errors if d.severity is Severity.ERROR}
    result = migrate(INVALID_V3)
    lines = result.text.splitlines()
    for number in rejected:
        flagged_at = lines.index(INVALID_V3.splitlines()[number - 1]) + 1
        assert [item.rule for item in result.manual if item.line == flagged_at] == ["X-COMMENTED"]


def test_v3_errors_mint_check_v3_misses_are_still_flagged_as_v4_errors() -> None:
    """FLY is write-only (v3:8013-8016) and an axis in brackets must be a number or a variable
    (v3:1006-1008) in v3 too; ``mint check --dialect v3`` does not say so, v4 does."""
    result = migrate("a = FLY\nSCALE[a+1] = 1000\n")
    assert {item.rule for item in result.manual} <= {"X-COMMENTED", "X-CHECK"}
    assert [item.line for item in result.manual] == [4, 6]  # below AXES[0,1,2], DIM a and each marker
