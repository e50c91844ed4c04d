"""A range printed as a list of values with gaps takes those values only.

ENCODERPRESCALE takes 1, 2, 4, 8, 16, 32, 64 or 128 (000:9680-9681) and MintDrive's
DRIVEENABLEOUTPUT -1, 0, 1, 2 or 4 (000:9340); a value between two of them, such as a prescale
of 3, is MML error 3 (000:18518). A list with no gap reads as its span ("0 or 1"; MintDrive's
MASTERSOURCE "2, 3", 000:13929).
"""

from __future__ import annotations

import pytest

import mintlang


def _codes(source: str, controller: str = "nextmove-pci") -> list[str]:
    return [d.code for d in mintlang.check(source, controller=controller)]


@pytest.mark.parametrize("value", ["1", "2", "16", "128"])
def test_a_listed_prescale_is_accepted(value: str) -> None:
    assert _codes(f"ENCODERPRESCALE.0 = {value}\n") == []


@pytest.mark.parametrize("value", ["3", "6", "100", "256", "0"])
def test_a_prescale_between_or_past_the_listed_ones_is_error_3(value: str) -> None:
    assert _codes(f"ENCODERPRESCALE.0 = {value}\n") == ["E0003"]


def test_mintdrive_takes_the_listed_drive_enable_outputs_only() -> None:
    assert _codes("DRIVEENABLEOUTPUT.0 = 4\nDRIVEENABLEOUTPUT.0 = -1\n", "mintdrive") == []
    assert _codes("DRIVEENABLEOUTPUT.0 = 3\n", "mintdrive") == ["E0003"]


def test_a_list_without_a_gap_is_its_span() -> None:
    assert _codes("MASTERSOURCE.0 = 2\nMASTERSOURCE.0 = 3\n", "mintdrive") == []
    assert _codes("MASTERSOURCE.0 = 4\n", "mintdrive") == ["E0003"]


def test_the_message_names_the_listed_values() -> None:
    (diagnostic,) = mintlang.check("ENCODERPRESCALE.0 = 3\n")
    assert "1, 2, 4, 8, 16, 32, 64, 128" in diagnostic.message
