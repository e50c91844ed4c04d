"""v3 CANCEL, DISLIMIT and RESET also turned contouring off; v4 CANCEL and RESET do not.

The v3 guide: "CANCEL will also turn contouring off" (001:6584), "DISLIMIT will also turn contouring
off" (001:7469), and RESET's table lists "CONTON* Contouring is switched off", the star marking what
CANCEL and DISLIMIT reset too (001:11427-11446). v4's CANCEL clears errors and crash stops, leaving
everything else (000:7985-8016); its RESET clears errors, zeroes the position and enables the drive
(000:15624-15629); contouring is CONTOURMODE, loaded with each move (000:8571-8575). So an XY program
that turned contouring on and recovers from an error with CANCEL went on with moves that stop at each
vertex in v3, and would go on blending them in v4: each of these statements gets what S-CONT writes
for CONTOFF after it, ``CONTOURMODE[0,1,2] = 0;``. One in the configuration file before the first
CONTON runs while contouring is still off, as at power-up, and is left as it is.
"""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate
from tests.migrate.helpers import rewritten

CASES = [
    pytest.param(
        "CONTON\nVECTORA = 10,10 : GO\nCANCEL\n",
        "CONTON\nVECTORA = 10,10 : GO\nCANCEL : CONTOURMODE[0,1,2] = 0;\n",
        id="CANCEL",
    ),
    pytest.param(
        'CONTON\nIF IN1 THEN CANCEL[0,1] : ? "cancelled"\n',
        'CONTON\nIF IN1 THEN CANCEL[0,1] : CONTOURMODE[0,1,2] = 0; : ? "cancelled"\n',
        id="in an IF body",
    ),
    pytest.param(
        "CONTON\nRESET.0 : REM start again\n",
        "CONTON\nRESET.0 : CONTOURMODE[0,1,2] = 0; : REM start again\n",
        id="RESET",
    ),
    pytest.param(
        "#ONERROR\n  CANCEL\nRETURN\nCONTON\n",
        "#ONERROR\n  CANCEL : CONTOURMODE[0,1,2] = 0;\nRETURN\nCONTON\n",
        id="a handler above the CONTON",
    ),
]


@pytest.mark.parametrize(("source", "expected"), CASES)
def test_contouring_is_turned_off_after_it(source: str, expected: str) -> None:
    assert rewritten("S-CONT-OFF", source) == expected


@pytest.mark.parametrize(("source", "expected"), CASES)
def test_the_migration_settles(source: str, expected: str) -> None:
    migrated = migrate(source, only=["S-CONT-OFF"])
    assert (migrated.text, migrated.manual) == (expected, ())
    assert migrate(migrated.text, only=["S-CONT-OFF"]).text == expected


def test_dislimit_turns_it_off_after_its_cancel() -> None:
    result = migrate("CONTON\nDISLIMIT.0\n", only=["S-LIMIT", "S-CONT-OFF"])
    assert result.text == ("CONTON\nLIMITMODE.0 = 0 : CANCEL.0 : DRIVEENABLE.0 = 1 : CONTOURMODE[0,1,2] = 0;\n")


def test_an_application_that_never_contours_is_left_alone() -> None:
    assert rewritten("S-CONT-OFF", "VECTORA = 10,10 : GO\nCANCEL\nRESET\n") == "VECTORA = 10,10 : GO\nCANCEL\nRESET\n"


def test_a_configuration_reset_before_the_first_conton_is_left_alone() -> None:
    result = migrate("CONTON\nCANCEL\n", config="RESET[0,1,2]\nCONTOFF\n", only=["S-CONT-OFF"])
    assert result.configuration is not None
    assert result.configuration.text == "RESET[0,1,2]\nCONTOFF\n"
    assert result.text == "CONTON\nCANCEL : CONTOURMODE[0,1,2] = 0;\n"


def test_a_controller_without_contouring_gets_nothing() -> None:
    # CONTON itself is S-CONT's manual item there ("CONTOURMODE is not available on MintDrive")
    assert rewritten("S-CONT-OFF", "CONTON\nCANCEL\n", controller="mintdrive") == "CONTON\nCANCEL\n"
