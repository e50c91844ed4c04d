"""S-ACCEL: the DECEL a v3 ACCEL write also set gets the value that write computed.

v3 copied the new ACCEL into DECEL on every ACCEL write (v3 guide, ACCEL 001:5662; DECEL 001:7203-7205);
v4 keeps the two apart (000:6178). ``ACCEL = ACCEL * 2;`` doubled the old rate in v3 and gave DECEL
that doubled rate. Written after the ACCEL, ``DECEL = ACCEL * 2;`` would read the rate already doubled
and set four times the old one, so the DECEL write goes first, where both read the old rate.
A value reading DECEL as well fits neither order and is left to a person.
"""

from __future__ import annotations

import pytest

from tests.migrate.helpers import flagged, migrated_twice, rewritten

CASES = [
    pytest.param("ACCEL = ACCEL * 2;\n", "DECEL = ACCEL * 2; : ACCEL = ACCEL * 2;\n", id="the default axes"),
    pytest.param(
        "ACCEL[1] = ACCEL.1 + 1000\n", "DECEL[1] = ACCEL.1 + 1000 : ACCEL[1] = ACCEL.1 + 1000\n", id="one axis"
    ),
    pytest.param(
        "IF a THEN ACCEL.0 = ACCEL.0 / 2 : b = 1\n",
        "IF a THEN DECEL.0 = ACCEL.0 / 2 : ACCEL.0 = ACCEL.0 / 2 : b = 1\n",
        id="in an IF body",
    ),
    pytest.param("ACCEL = 2000;\n", "ACCEL = 2000; : DECEL = 2000;\n", id="a value not reading ACCEL: after"),
]


@pytest.mark.parametrize(("source", "expected"), CASES)
def test_decel_is_written_from_the_value_the_accel_write_computed(source: str, expected: str) -> None:
    assert rewritten("S-ACCEL", source) == expected


@pytest.mark.parametrize(("source", "expected"), CASES)
def test_the_migration_settles(source: str, expected: str) -> None:
    assert migrated_twice("S-ACCEL", source) == (expected, (), expected, ())


def test_a_value_reading_accel_and_decel_is_left_for_a_person() -> None:
    assert flagged("S-ACCEL", "ACCEL = ACCEL + DECEL\n") == [
        "the value reads ACCEL and DECEL: v4 needs DECEL written too; compute the value into a variable first"
    ]
