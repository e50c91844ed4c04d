"""CONTOURANGLE is an angle of 0 to 180 degrees, whatever the scale factor.

Its attributes table ticks Scaled and prints "0 to 180" (000:8524-8527), but its description
gives the threshold in degrees between 0 and 180 (000:8533): an angle is not a position, so the
scale factor does not apply and a value above 180 is MML error 3 (000:18518).
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.keyworddb import database


def _codes(source: str) -> list[str]:
    return [d.code for d in mintlang.check(source, controller="nextmove-pci")]


@pytest.mark.parametrize("value", ["0", "15", "180"])
def test_an_angle_up_to_180_degrees_is_accepted(value: str) -> None:
    assert _codes(f"CONTOURANGLE.0 = {value}\n") == []


@pytest.mark.parametrize("value", ["181", "360", "-1"])
def test_an_angle_outside_0_to_180_degrees_is_error_3(value: str) -> None:
    assert _codes(f"CONTOURANGLE.0 = {value}\n") == ["E0003"]


def test_the_keyword_notes_say_the_description_is_followed_over_the_table() -> None:
    notes = " ".join(database().keywords["CONTOURANGLE"].notes)
    assert "ticks Scaled" in notes and "degrees" in notes
