"""A range printed as named modes allows exactly those values.

MOTORDIRECTION's attributes print its range as "0 – Forward, 1 – Reverse" (000:14092-14111,
MintDrive): 0 and 1 are its only values, so writing 2 is out of range (MML error 3, 000:18518).
"""

from __future__ import annotations

import pytest

import mintlang


def _codes(source: str) -> list[str]:
    return [d.code for d in mintlang.check(source, controller="mintdrive")]


@pytest.mark.parametrize("value", ["0", "1"])
def test_a_named_mode_is_accepted(value: str) -> None:
    assert _codes(f"MOTORDIRECTION = {value}\n") == []


@pytest.mark.parametrize("value", ["2", "-1"])
def test_another_value_is_error_3(value: str) -> None:
    assert _codes(f"MOTORDIRECTION = {value}\n") == ["E0003"]
