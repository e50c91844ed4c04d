"""S-ANALOG: ANALOGUEn reads become ADC.(n-1) converted to v3 counts, always with a manual item."""

from __future__ import annotations

from mintlang.migrate import migrate
from tests.migrate.helpers import flagged, one_rule, rewritten


def _note(channel: int) -> str:
    return (
        f"ADC.{channel} is % of the input range: the v3 count formula assumes a +-10 V input "
        f"(0..5 V input: INT(ADC.{channel} * 1024 / 50)); check the wiring and simplify"
    )


def test_reads_are_converted_and_each_gets_a_manual_item() -> None:
    result = one_rule("S-ANALOG", "JOG = A1 - 512, analogue2 - 512 : REM joystick\nx = ANALOGUE3\n")
    assert result.text == (
        f"REM MIGRATE: S-ANALOG: {_note(0)}\nREM MIGRATE: S-ANALOG: {_note(1)}\n"
        "JOG = (INT((ADC.0 + 100) * 1024 / 200) - (ADC.0 >= 100)) - 512, "
        "(int((adc.1 + 100) * 1024 / 200) - (adc.1 >= 100)) - 512 : REM joystick\n"
        f"REM MIGRATE: S-ANALOG: {_note(2)}\nx = INT((ADC.2 + 100) * 1024 / 200) - (ADC.2 >= 100)\n"
    )
    assert [item.line for item in result.manual] == [3, 3, 5]


def test_a_read_inside_an_expression_is_bracketed_once() -> None:
    assert "y = 2 * (INT((ADC.0 + 100) * 1024 / 200) - (ADC.0 >= 100))\n" in rewritten("S-ANALOG", "y = 2 * (A1)\n")
    assert "y = (INT((ADC.0 + 100) * 1024 / 200) - (ADC.0 >= 100)) * 2\n" in rewritten("S-ANALOG", "y = A1 * 2\n")


def test_missing_channel_is_manual() -> None:
    assert flagged("S-ANALOG", "x = A2\n", controller="servonode51") == ["ServoNode 51 has no ADC.1"]


def test_second_run_changes_nothing() -> None:
    first = migrate("x = A1 - 512\n")
    second = migrate(first.text)
    assert second.text == first.text and second.changes == ()
    assert [(item.rule, item.line) for item in second.manual] == [(item.rule, item.line) for item in first.manual]


def test_untouched_bytes_survive() -> None:
    text = rewritten("S-ANALOG", "\tx=A1*2\t:rem  KEEP\r\n")
    assert text.endswith("\tx=(INT((ADC.0 + 100) * 1024 / 200) - (ADC.0 >= 100))*2\t:rem  KEEP\r\n")
