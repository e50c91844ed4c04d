"""A bit mask takes every combination of the bits its entry documents, whatever its table prints.

CAM's attributes table prints 0 ≤ x ≤ 15 (000:7563), but its bit table goes on to bit 4,
_cmTRIGGER, and bit 5, _cmRETRIGGER, which needs bit 4 set too (000:7593-7621): the entry's
own combination _cmTRIGGER + _cmRETRIGGER is 48. CONTOURMODE's table prints 0 or 1
(000:8567), but its bit 1 turns inter-vector angle control on and the entry gives the mode's
valid range as 0 to 3 (000:8643-8654). Values past every documented bit stay MML error 3
(000:18518).
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.keyworddb import database


def _codes(source: str) -> list[str]:
    return [d.code for d in mintlang.check(source, controller="nextmove-pci")]


@pytest.mark.parametrize(
    "source",
    [
        "CAM.0 = _cmTRIGGER + _cmRETRIGGER\n",
        "CAM.0 = _cmABSOLUTE + _cmCONTINUOUS + _cmTRIGGER\n",
        "CAM.0 = 63\n",
        "CONTOURMODE = _ctmCONTOUR_ON + _ctmVECTOR_ANGLE_ON\n",
        "CONTOURMODE = 3\n",
    ],
)
def test_a_combination_of_documented_bits_is_in_range(source: str) -> None:
    assert _codes(source) == []


@pytest.mark.parametrize("source", ["CAM.0 = 64\n", "CAM.0 = -1\n", "CONTOURMODE = 4\n"])
def test_a_value_past_the_documented_bits_is_error_3(source: str) -> None:
    assert _codes(source) == ["E0003"]


def test_the_message_gives_the_range_the_bits_make() -> None:
    (diagnostic,) = mintlang.check("CAM.0 = 64\n")
    assert "0 ≤ x ≤ 63" in diagnostic.message


@pytest.mark.parametrize("keyword", ["CAM", "CONTOURMODE"])
def test_the_keyword_notes_record_the_printed_range_and_the_bits(keyword: str) -> None:
    notes = " ".join(database().keywords[keyword].notes)
    assert "attributes table" in notes and "bits" in notes
