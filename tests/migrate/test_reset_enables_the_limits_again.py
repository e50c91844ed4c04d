"""v3 RESET enabled the limits a DISLIMIT had turned off; v4 RESET leaves LIMITMODE as it is.

The v3 guide's DISLIMIT entry: "Issuing a RESET command will re-enable the limits" (001:7471), and
RESET's table lists "DISLIMIT Limits are enabled" (001:11427-11446), without the star of what CANCEL
resets too. v4 RESET clears errors, zeroes the position, enables the drive and crash stops
(000:15624-15629); limit detection is LIMITMODE (000:13446-13497), which S-LIMIT writes 0 for a
DISLIMIT and 1 for an ENLIMIT. So a v3 program that drove off a limit with DISLIMIT and recovered with
RESET ran on with its limits watched; migrated as it was, it would run with them off. Each RESET that
can run after a DISLIMIT gets ``LIMITMODE<the same axes> = 1`` after it, as ENLIMIT becomes; one in the
configuration file before the first DISLIMIT is left as it is, the limits being as at power-up.
"""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate
from tests.migrate.helpers import rewritten

CASES = [
    pytest.param(
        "#ONERROR\n  DISLIMIT[0,1]\n  PAUSE !LIMIT[0,1]\n  RESET[0,1]\nRETURN\n",
        "#ONERROR\n  DISLIMIT[0,1]\n  PAUSE !LIMIT[0,1]\n  RESET[0,1] : LIMITMODE[0,1] = 1;\nRETURN\n",
        id="the axes named",
    ),
    pytest.param("DISLIMIT.1\nRESET.1\n", "DISLIMIT.1\nRESET.1 : LIMITMODE.1 = 1\n", id="one axis"),
    pytest.param("RESET : REM again\nDISLIMIT\n", "RESET : LIMITMODE = 1; : REM again\nDISLIMIT\n", id="default axes"),
]


@pytest.mark.parametrize(("source", "expected"), CASES)
def test_the_limits_are_enabled_again(source: str, expected: str) -> None:
    assert rewritten("S-LIMIT-RESET", source) == expected


@pytest.mark.parametrize(("source", "expected"), CASES)
def test_the_migration_settles(source: str, expected: str) -> None:
    migrated = migrate(source, only=["S-LIMIT-RESET"])
    assert (migrated.text, migrated.manual) == (expected, ())
    assert migrate(migrated.text, only=["S-LIMIT-RESET"]).text == expected


def test_cancel_leaves_them_off_as_in_v3() -> None:
    assert rewritten("S-LIMIT-RESET", "DISLIMIT.0\nCANCEL.0\n") == "DISLIMIT.0\nCANCEL.0\n"


def test_an_application_that_never_disables_them_is_left_alone() -> None:
    assert rewritten("S-LIMIT-RESET", "RESET[0,1]\nENLIMIT.0\n") == "RESET[0,1]\nENLIMIT.0\n"


def test_a_configuration_reset_before_the_first_dislimit_is_left_alone() -> None:
    result = migrate("DISLIMIT.0\n", config="RESET[0,1,2]\n", only=["S-LIMIT-RESET"])
    assert result.configuration is not None
    assert result.configuration.text == "RESET[0,1,2]\n"


def test_with_contouring_both_follow_the_reset() -> None:
    result = migrate("CONTON\nDISLIMIT.0\nRESET.0\n", only=["S-LIMIT-RESET", "S-CONT-OFF"])
    assert result.text.splitlines()[2] in (
        "RESET.0 : CONTOURMODE[0,1,2] = 0; : LIMITMODE.0 = 1",
        "RESET.0 : LIMITMODE.0 = 1 : CONTOURMODE[0,1,2] = 0;",
    )
    assert migrate(result.text, only=["S-LIMIT-RESET", "S-CONT-OFF"]).text == result.text
