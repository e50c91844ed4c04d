"""Manual items: the original stays, a REM MIGRATE line sits above it with the same
indentation, and the report lists it with the line it flags."""

from __future__ import annotations

import pytest

import mintlang
from mintlang.migrate import migrate
from tests.migrate.helpers import flagged


def test_marker_goes_above_with_the_same_indentation() -> None:
    result = migrate("LOOP\n    LOAD 3\nENDL\n", only=["X-HOST"])
    assert result.text == (
        "LOOP\n    REM MIGRATE: X-HOST: LOAD: no Mint v4 keyword (Mint WorkBench transfers programs and arrays): "
        "remove or redesign\n    LOAD 3\nENDL\n"
    )
    assert [(item.rule, item.line) for item in result.manual] == [("X-HOST", 3)]


_RAMP = "REM MIGRATE: S-RAMP: SRAMP shapes the ramps differently from v3 RAMP: check the motion"


def test_nothing_goes_above_auto_its_line_is_broken_after_it() -> None:
    """AUTO must be the first command of the configuration file, REM lines included, or the
    application does not start at power-up (v4:6647-6649): a flag for a statement after it on its
    line breaks the line after AUTO (a line end separates statements as ``:`` does)."""
    result = migrate("", config="AUTO : RAMP = 5;\nSCALE = 1;\n", controller="nextmove-bx")
    configuration = result.configuration
    assert configuration is not None
    assert configuration.text == f"AUTO\nAXES[0,1,2]\n{_RAMP}\nSRAMP = 50;\nSCALE = 1;\n"
    assert [(item.rule, item.line) for item in configuration.manual] == [("S-RAMP", 4)]
    assert [(c.line, c.original) for c in configuration.changes if c.rule == "S-RAMP"] == [(1, " : "), (1, "RAMP = 5;")]
    again = migrate("", config=configuration.text, controller="nextmove-bx").configuration
    assert again is not None and again.text == configuration.text and again.changes == ()


def test_a_flag_alone_after_auto_or_protect_breaks_only_the_separator() -> None:
    result = migrate("x = 1\r\n", config="AUTO : ERRORIN = 1\r\nSCALE = 1\r\n", only=["S-ERRORIN"])
    assert result.configuration is not None
    marker = "REM MIGRATE: S-ERRORIN: ERRORINPUT takes the error input's number (-1 none); set its level with "
    marker += "INPUTACTIVELEVEL"
    assert result.configuration.text == f"AUTO\r\n{marker}\r\nERRORIN = 1\r\nSCALE = 1\r\n"
    assert [(item.rule, item.line) for item in result.configuration.manual] == [("S-ERRORIN", 3)]


@pytest.mark.parametrize(
    ("rule", "source"),
    [
        ("X-PULSE", "PULSE = 1\n"),
        ("X-INCA", "INCR = 5\n"),
        ("X-SERVON", "SERVON.0\n"),
        ("X-TRIGGER", "TRIGGER = 1\n"),
        ("X-IO-EXP", "x = XENCODER\n"),
        ("X-KEYPAD", 'KEYS ""\n'),
        ("X-HOST", "SAVE 3\n"),
        ("X-AXISCON", "AXISCON = 1\n"),
        ("X-MISC-ABSENT", "DATETIME = 4000\n"),
        ("X-ENABLE", "ENABLE = 1\n"),
        ("X-ERR", "IF ERR = 15 THEN x = 1\n"),
        ("X-CHANGED", "DISPLAY\n"),
        ("X-PROTECT", "PROTECT my pass, 1!\n"),
        ("X-ONERROR", "#ONERROR\nRETURN\n"),
        ("X-FASTLATCH", "#FASTPOS\nRETURN\n"),
        ("X-COMMENTED", "RME Project\n"),
        ("X-PLATFORM", "AUTO\n"),
        ("X-V3", "x = _limit\n"),
    ],
)
def test_each_manual_rule_flags_and_keeps_the_original(rule: str, source: str) -> None:
    assert len(flagged(rule, source)) == 1


_OPTION_CARD = "replaced by DPRFLOAT/DPRLONG/DPRWORD, which address dual-port RAM, not the option card: redesign"


@pytest.mark.parametrize(
    ("source", "reason"),
    [
        ("PRINT PEEK(10)\n", f"PEEK: {_OPTION_CARD}"),  # v3:10750; v4:15065-15066
        ("a = PK(3)\n", f"PEEK: {_OPTION_CARD}"),
        ("POKE 1,127\n", f"POKE: {_OPTION_CARD}"),  # v3:10821; v4:15079-15080
    ],
)
def test_option_card_reads_and_writes_are_flagged_as_another_address_space(source: str, reason: str) -> None:
    assert flagged("X-HOST", source) == [reason]


def test_every_read_of_err_is_flagged() -> None:
    # v3 numbered errors 0 .. 15, 0 being Out of range (v3:4918-4937); v4's numbers are others, a motion
    # error 500 (v4:18503-18893): a printed or stored code shows another number, and IF ERR tests another
    assert len(flagged("X-ERR", "IF (ERR) >= 10 AND ERR < 15 THEN x = 1\n")) == 1  # one flag a statement
    assert len(flagged("X-ERR", "PRINT ERR\nIF ERR THEN x = 1\ncode = ERR\n")) == 3


def test_invalid_v3_structure_and_labels_are_reported() -> None:
    assert flagged("X-COMMENTED", "GOSUB missing\n#a\nRETURN\n#a\nRETURN\nENDIF\n") == [
        "label #missing is not in this file",
        "label #a is defined twice",
        "blocks do not match: ELSE/ENDIF w/o IF DO: ENDIF without IF .. DO",
    ]


def test_leftover_catch_all_does_not_repeat_an_earlier_item() -> None:
    result = migrate("DISPLAY\n", only=["X-CHANGED", "X-V3"])
    assert [item.rule for item in result.manual] == ["X-CHANGED"]


def test_migrated_text_that_is_already_v4_is_not_flagged() -> None:
    source = "KPROP = 2;\nEVENTDISABLE = EVENTDISABLE | 0xA0\nIF (AXISMODE & _mdJOG) THEN x = 1\n"
    assert migrate(source, only=["X-COMMENTED", "X-V3", "X-PLATFORM"]).manual == ()


def test_a_comment_missing_its_rem_after_a_command_is_reported() -> None:
    # "STOP following" in the v3 listings (v3:3727, v3:3790): STOP takes no operands in either version
    assert flagged("X-COMMENTED", "STOP.0 : STOP following\n") == ["STOP takes no operands (a comment missing REM?)"]


def test_a_keyword_whose_entry_lists_no_controllers_is_not_a_platform_item() -> None:
    # MOVESTATUS's entry defers to the Advanced guide and names no controllers (000:14634-14636): mint check
    # takes it as every controller's, so X-PLATFORM must not say the target lacks it
    assert migrate("a = MOVESTATUS.0\nPRINT a\n", only=["X-PLATFORM"]).manual == ()
    assert [d.code for d in mintlang.check("DIM a\na = MOVESTATUS.0\nPRINT a\n")] == []


def test_a_v3_password_is_the_rest_of_its_line_and_v4_reads_one_word() -> None:
    # v3: the rest of line 1 is the password, a colon and keywords included (v3:11089-11092), so INCR
    # here is no statement to flag; v4 would run it after a password of letters and digits (v4:15393)
    program = migrate("PROTECT pw : INCR = 5\nx = 1\n")
    assert [item.rule for item in program.manual] == ["X-PROTECT"]
    assert "PROTECT pw : INCR = 5\n" in program.text
    assert flagged("X-PROTECT", "PROTECT tincan\n") == []
