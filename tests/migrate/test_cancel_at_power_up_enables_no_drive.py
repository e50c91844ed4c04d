"""A v3 CANCEL run before anything switched the amplifiers on leaves them off, so its migration enables no drive.

The v3 guide: the amplifier enable keeps the amplifiers disabled from power-up until a RESET or CONFIG
(001:11409-11411), or ENABLE = 1 (001:7567-7576); CANCEL recovers them after a motion error switched them
off (001:5004-5006). S-CANCEL writes DRIVEENABLE after a CANCEL for that recovery (000:15628); after one at
power-up, the first lines of the file that runs first, it would enable the drives v3 kept disabled. Where the
lines above the CANCEL can have run after such a switch (a label, a jump, a loop, RUN, an event handler of
that file), the DRIVEENABLE is written as before.
"""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate
from mintlang.migrate.verification import Verdict, verify


def _cancel_rewritten(source: str, config: str | None = None) -> str:
    result = migrate(source, config=config, only=["S-CANCEL"])
    return result.configuration.text if config is not None and result.configuration is not None else result.text


@pytest.mark.parametrize(
    "source",
    [
        pytest.param("CANCEL\nMOVEA.0 = 10 : GO.0\n", id="the program's first line"),
        pytest.param("PRINT 1 : CANCEL[0,1]\nIF IN1 THEN CANCEL\n", id="before any RESET, CONFIG or ENABLE"),
        pytest.param("ENABLE = _off\nCANCEL\nENABLE = 0 : CANCEL\n", id="after ENABLE switched them off"),
    ],
)
def test_a_cancel_at_power_up_enables_no_drive(source: str) -> None:
    assert _cancel_rewritten(source) == source


def test_a_cancel_at_the_top_of_the_configuration_enables_no_drive() -> None:
    assert _cancel_rewritten("CANCEL\n", config="AUTO\nCANCEL\nRESET\n") == "AUTO\nCANCEL\nRESET\n"


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        pytest.param("RESET\nCANCEL\n", "RESET\nCANCEL : DRIVEENABLE = 1;\n", id="after RESET"),
        pytest.param("ENABLE = 1\nCANCEL\n", "ENABLE = 1\nCANCEL : DRIVEENABLE = 1;\n", id="after ENABLE"),
        pytest.param("LOOP\nCANCEL\nRESET\nENDL\n", "LOOP\nCANCEL : DRIVEENABLE = 1;\nRESET\nENDL\n", id="in a loop"),
        pytest.param("GOSUB a\nCANCEL\nEND\n#a\nRESET\nRETURN\n", None, id="after a jump"),
        pytest.param("CANCEL\n#ONERROR\nRESET\nRETURN\n", None, id="beside an event handler"),
        pytest.param("CANCEL\nRUN\n", None, id="with RUN"),
    ],
)
def test_a_cancel_that_can_follow_a_switch_on_enables_the_drive(source: str, expected: str | None) -> None:
    assert "CANCEL : DRIVEENABLE = 1;" in _cancel_rewritten(source)
    if expected is not None:
        assert _cancel_rewritten(source) == expected


def test_a_cancel_in_the_program_after_the_configuration_reset_enables_the_drive() -> None:
    assert _cancel_rewritten("CANCEL\n", config="RESET\n") == "RESET\n"
    assert migrate("CANCEL\n", config="RESET\n", only=["S-CANCEL"]).text == "CANCEL : DRIVEENABLE = 1;\n"


def test_the_migrated_program_refuses_the_move_as_v3_did() -> None:
    # v3: "Servo off" (001:13169-13171); v4: the drive disabled, error 40 (000:18659)
    verification = verify(migrate("CANCEL\nMOVEA.0 = 10 : GO.0\nPAUSE IDLE.0\nPRINT POS.0\n"), until_ms=100)
    assert verification.verdict is not Verdict.DIVERGES, verification.divergence
