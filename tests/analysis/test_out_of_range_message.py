"""Error 3 names the value as written, whole, at the value's place.

TIME's range is 0 to 16777215 on NextMove and 0 to 65535 on MintDrive (000:16746-16747); one more
is MML error 3, data out of range (000:18518). The message printed 16777216 as 1.67772e+07.
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.placed import placed_codes


@pytest.mark.parametrize(
    ("controller", "value", "shown"),
    [
        ("nextmove-pci", "16777216", "16777216 is outside the range of TIME (0 ≤ x ≤ 16777215)"),
        ("mintdrive", "65536", "65536 is outside the range of TIME (0 ≤ x ≤ 65535)"),
        ("nextmove-pci", "16777215.5", "16777215.5 is outside the range of TIME (0 ≤ x ≤ 16777215)"),
    ],
)
def test_the_message_shows_the_value_in_full(controller: str, value: str, shown: str) -> None:
    (diagnostic,) = mintlang.check(f"TIME = {value}\n", controller=controller)
    assert diagnostic.code == "E0003" and shown in diagnostic.message


def test_a_constant_is_named_beside_its_value() -> None:
    # MintDrive's DRIVEENABLEOUTPUT takes -1, 0, 1, 2 or 4 (000:9338), no relay: _RELAY0 is 1000 (000:9362)
    (diagnostic,) = mintlang.check("DRIVEENABLEOUTPUT.0 = _RELAY0\n", controller="mintdrive")
    assert diagnostic.code == "E0003"
    assert diagnostic.message.endswith("_RELAY0 (1000) is outside the range of DRIVEENABLEOUTPUT (-1, 0, 1, 2, or 4)")


def test_the_error_points_at_the_value() -> None:
    assert placed_codes("TIME = 0\nTIME = 16777216\n") == [("E0003", 2, 8)]


@pytest.mark.parametrize("value", ["0", "-1"])
def test_scale_takes_only_a_positive_value(value: str) -> None:
    # 000:532-537: SCALE only accepts a positive value (its table prints 0 ≤ x; mint-run stops on 0 with R0003)
    (diagnostic,) = mintlang.check(f"SCALE = {value}\n")
    assert diagnostic.code == "E0003" and "SCALE" in diagnostic.message


def test_a_positive_scale_is_in_range() -> None:
    assert mintlang.check("SCALE = 500, 500\n") == []
