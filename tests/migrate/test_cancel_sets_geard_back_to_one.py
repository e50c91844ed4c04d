"""S-GEAR: a gearbox whose GEARD a CANCEL, DISLIMIT or RESET can set back to 1 is left for a person.

v3's CANCEL and DISLIMIT "reset GEARN and GEARD to 0 and 1 respectively" (001:6584, 001:7469), and so
does RESET (its table, 001:11427-11446). A program that sets ``GEARD = 10`` once and starts following
with ``GEARN = 5`` geared at 5/10 until an error handler's CANCEL, and at 5/1 after it. S-GEAR folds the
one GEARD it finds into ``FOLLOW = 5 / 10`` (or keeps it as FOLLOWDENOM on MintDrive), which v4's CANCEL
and RESET leave as they are (000:7985-8016, 000:15624-15629): the ratio after the reset is not the
one v3 used, so neither statement can be rewritten as proven. A reset of the configuration file, which
runs before the program's GEARD, a reset of another axis and a GEARD of 1 change nothing.
"""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate
from tests.migrate.helpers import flagged

REASON = "a CANCEL, DISLIMIT or RESET of axis 0 sets its GEARD back to 1 in v3: write FOLLOW = n / d by hand"


@pytest.mark.parametrize("reset", ["CANCEL", "DISLIMIT.0", "RESET[0,1]"])
@pytest.mark.parametrize("controller", ["nextmove-pci", "mintdrive"])
def test_a_reset_in_the_program_leaves_the_ratio_unproven(reset: str, controller: str) -> None:
    source = f"GEARD.0 = 10\nLOOP\n  GEARN.0 = 5\n  PAUSE IN1\nENDL\n#ONERROR\n  {reset}\nRETURN\n"
    assert flagged("S-GEAR", source, controller=controller) == [REASON, REASON]


def test_a_configuration_reset_before_the_gearbox_changes_nothing() -> None:
    result = migrate("GEARD.0 = 10\nGEARN.0 = 5\n", config="RESET[0,1,2]\n", only=["S-GEAR"])
    assert result.text == "REM GEARD.0 = 10: folded into FOLLOW = n / d by mint-migrate\nFOLLOW.0 = 5 / 10\n"


def test_a_reset_of_another_axis_changes_nothing() -> None:
    result = migrate("GEARD.0 = 10\nGEARN.0 = 5\nCANCEL.1\n", only=["S-GEAR"])
    assert result.text == "REM GEARD.0 = 10: folded into FOLLOW = n / d by mint-migrate\nFOLLOW.0 = 5 / 10\nCANCEL.1\n"


def test_a_denominator_of_one_is_what_the_reset_sets() -> None:
    result = migrate("GEARD.0 = 1\nGEARN.0 = 5\nCANCEL\n", only=["S-GEAR"])
    assert result.text == "REM GEARD.0 = 1: folded into FOLLOW = n / d by mint-migrate\nFOLLOW.0 = 5 / 1\nCANCEL\n"
