"""A v3 entry's Format heading is read with or without its colon: RAMP's alone prints none (001:11204), and its
formats ``RAMP[axes] = ...`` and ``v = RAMP[axis]`` (001:11207-11208) address axes, as its table's Multi-Axis tick
says (001:11212), so hover on it in a v3 file and the migrator's view of it know it addresses axes."""

from __future__ import annotations

from mintlang.keyworddb import database
from mintlang.keyworddb.model import Addressing


def test_ramp_addresses_axes() -> None:
    assert database().v3_keywords["RAMP"].addressing is Addressing.AXIS
