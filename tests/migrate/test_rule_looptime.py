"""S-LOOPTIME: LOOPTIME 1/2 (ms) becomes 1000/2000 (us) where v4 documents those values."""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate
from tests.migrate.helpers import flagged, rewritten


@pytest.mark.parametrize("controller", ["mintdrive", "servonode51"])
def test_milliseconds_become_microseconds(controller: str) -> None:
    source = "LOOPTIME = 1\nlt = 2 : REM keep\n"
    assert rewritten("S-LOOPTIME", source, controller=controller) == "LOOPTIME = 1000\nlt = 2000 : REM keep\n"


def test_values_already_in_microseconds_are_left_alone() -> None:
    source = "LOOPTIME = 500\nLOOPTIME = 2000\n"
    assert rewritten("S-LOOPTIME", source, controller="mintdrive") == source


def test_nextmove_keeps_the_statement_with_a_manual_item() -> None:
    reasons = flagged("S-LOOPTIME", "LOOPTIME = 2\n")
    assert reasons == [
        "NextMove PCI servos every 1 ms and profiles every 2 ms (v4 guide section 2.1.1): "
        "remove this LOOPTIME or see the Advanced Programming Guide"
    ]


@pytest.mark.parametrize(
    ("source", "reason"),
    [
        ("LOOPTIME = t\n", "LOOPTIME value is not 1 or 2: v4 takes 500, 1000 or 2000 us"),
        ("x = LOOPTIME\n", "LOOPTIME reads microseconds in v4 (v3: milliseconds)"),
    ],
)
def test_computed_values_and_reads_are_manual(source: str, reason: str) -> None:
    assert flagged("S-LOOPTIME", source, controller="mintdrive") == [reason]


@pytest.mark.parametrize("controller", ["mintdrive", "nextmove-pci"])
def test_second_run_changes_nothing(controller: str) -> None:
    first = migrate("LOOPTIME = 1\n", controller=controller)
    second = migrate(first.text, controller=controller)
    assert second.text == first.text and second.changes == ()
