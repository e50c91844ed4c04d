"""A writable range holds the keyword's own default, whatever its table prints.

AUXENCODERWRAP's attributes table prints 1.0 ≤ x ≤ 8388607.0 on NextMove and 1 ≤ x ≤ 65535
on MintDrive, with a default of 0.0 and 0 (000:6847-6848), and its entry turns the wrap off
by writing that value: "a wrap value of 0.0 is given" (000:6865). The guide's own way of
turning the wrap off cannot be out of range (error 3); a negative wrap or one past the
maximum still is.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.keyworddb import database


def _codes(source: str, controller: str) -> list[str]:
    return [d.code for d in mintlang.check(source, controller=controller)]


@pytest.mark.parametrize("controller", ["nextmove-pci", "mintdrive"])
def test_writing_the_default_to_turn_the_wrap_off_is_in_range(controller: str) -> None:
    assert _codes("AUXENCODERWRAP.0 = 360\nAUXENCODERWRAP.0 = 0.0\n", controller) == []


@pytest.mark.parametrize("value", ["-1", "8388608"])
def test_a_wrap_outside_the_printed_range_and_the_default_is_error_3(value: str) -> None:
    assert _codes(f"AUXENCODERWRAP.0 = {value}\n", "nextmove-pci") == ["E0003"]


def test_the_keyword_notes_record_the_printed_range_and_the_default() -> None:
    notes = " ".join(database().keywords["AUXENCODERWRAP"].notes)
    assert "1.0 ≤ x ≤ 8388607.0 (default 0.0)" in notes
