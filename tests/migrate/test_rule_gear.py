"""S-GEAR: GEARD/GEARN become FOLLOWDENOM/FOLLOW (or FOLLOW = n / d), with explicit axes."""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate
from tests.migrate.helpers import flagged, one_rule, rewritten


def test_mintdrive_keeps_numerator_and_denominator() -> None:
    source = "GEARD = 10\nGEARN = 2 : REM 0.2\n"
    assert rewritten("S-GEAR", source, controller="mintdrive") == "FOLLOWDENOM.0 = 10\nFOLLOW.0 = 2 : REM 0.2\n"


def test_nextmove_folds_the_denominator_into_follow() -> None:
    result = one_rule("S-GEAR", "GEARD[0,1] = 10, 4\nGEARN[0,1] = 2, 1\n")
    assert result.text == (
        "REM GEARD[0,1] = 10, 4: folded into FOLLOW = n / d by mint-migrate\n"
        "REM MIGRATE: S-GEAR: FOLLOW = n / d is a float ratio: v3's n/d could not drift\n"
        "FOLLOW[0,1] = 2 / 10, 1 / 4\n"
    )


def test_an_exact_float_ratio_needs_no_manual_item() -> None:
    assert one_rule("S-GEAR", "GEARD.1 = 4\nGEARN.1 = -3\n").manual == ()


def test_out_of_range_denominator_uses_the_ratio_with_followdenom_one() -> None:
    result = one_rule("S-GEAR", "GEARD = 1000\nGEARN = 5\n", controller="mintdrive")
    assert result.text == (
        "FOLLOWDENOM.0 = 1\n"
        "REM MIGRATE: S-GEAR: FOLLOW = n / d is a float ratio: v3's n/d could not drift\n"
        "FOLLOW.0 = 5 / 1000\n"
    )


def test_masterinc_means_clutch_mode() -> None:
    source = "MASTERINC.0 = 1000\nGEARD = 10\nGEARN = 2\n"
    text = rewritten("S-GEAR", source, controller="mintdrive")
    assert text == "MASTERINC.0 = 1000\nFOLLOWDENOM.0 = 10\nFOLLOWMODE.0 = _fmCLUTCH : FOLLOW.0 = 2\n"


@pytest.mark.parametrize(
    ("source", "reason"),
    [
        ("GEARN = 2\n", "no GEARD for axis 0: v3 needs GEARD before GEARN"),
        ("GEARD = d\nGEARN = 2\n", "GEARD of axis 0 is computed or takes several values: write FOLLOW = n / d by hand"),
        ("GEARD = 2\nGEARD = 3\n", "GEARD of axis 0 is computed or takes several values: write FOLLOW = n / d by hand"),
        ("GEARD = 1\nGEARN = 300\n", "a gear ratio of axis 0 is outside FOLLOW's -128..127"),
        ("MASTERINC = 1\nGEARD = 2\n", "MASTERINC of axis 0 may be 1 (v3: no clutch): choose FOLLOWMODE by hand"),
        ("GEARD.(a) = 2\n", "the axes are not constant: write FOLLOW[axes] = n / d by hand"),
        ("x = GEARN.0\n", "reading GEARN: read FOLLOW (the ratio) in v4"),
    ],
)
def test_unproven_context_is_manual(source: str, reason: str) -> None:
    assert reason in flagged("S-GEAR", source, controller="mintdrive")


def test_a_computed_numerator_refuses_both_statements() -> None:
    assert (
        flagged("S-GEAR", "GEARD = 2\nGEARN = n\n")
        == ["GEARN of axis 0 is computed: FOLLOW takes -128..127, write FOLLOW = n / d by hand"] * 2
    )


def test_geard_sharing_its_line_on_nextmove_is_manual() -> None:
    result = one_rule("S-GEAR", "GEARD = 4 : GEARN = 1\n")
    assert result.text == (
        "REM MIGRATE: S-GEAR: NextMove PCI has no FOLLOWDENOM: FOLLOW takes n / d; delete this GEARD\n"
        "GEARD = 4 : FOLLOW.0 = 1 / 4\n"
    )


@pytest.mark.parametrize("controller", ["mintdrive", "nextmove-pci"])
def test_second_run_changes_nothing(controller: str) -> None:
    first = migrate("MASTERINC = 500\nGEARD = 10\nGEARN = 8\n", controller=controller)
    second = migrate(first.text, controller=controller)
    assert second.text == first.text and second.changes == ()
    assert [(item.rule, item.line) for item in second.manual] == [(item.rule, item.line) for item in first.manual]


def test_untouched_bytes_survive() -> None:
    source = "REM\tgear\r\n\tgd = 10\t: rem  den\r\n\tgr = 5\r\n"
    assert rewritten("S-GEAR", source, controller="mintdrive") == (
        "REM\tgear\r\n\tfollowdenom.0 = 10\t: rem  den\r\n\tfollow.0 = 5\r\n"
    )
