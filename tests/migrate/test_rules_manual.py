"""Manual items: the original stays, a REM MIGRATE line sits above it with the same
indentation, and the report lists it with the line it flags."""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate
from tests.migrate.helpers import flagged


def test_marker_goes_above_with_the_same_indentation() -> None:
    result = migrate("LOOP\n    LOAD 3\nENDL\n", only=["X-HOST"])
    assert result.text == (
        "LOOP\n    REM MIGRATE: X-HOST: LOAD: no Mint v4 keyword (Mint WorkBench transfers programs and arrays): "
        "remove or redesign\n    LOAD 3\nENDL\n"
    )
    assert [(item.rule, item.line) for item in result.manual] == [("X-HOST", 3)]


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
        ("X-ONERROR", "#ONERROR\nRETURN\n"),
        ("X-FASTLATCH", "#FASTPOS\nRETURN\n"),
        ("X-COMMENTED", "RME Project\n"),
        ("X-PLATFORM", "AUTO\n"),
        ("X-V3", "x = _limit\n"),
    ],
)
def test_each_manual_rule_flags_and_keeps_the_original(rule: str, source: str) -> None:
    assert len(flagged(rule, source)) == 1


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
