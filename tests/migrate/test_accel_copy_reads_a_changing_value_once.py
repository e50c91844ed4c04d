"""S-ACCEL: a DECEL copy of a value that changes between two reads takes what the ACCEL write got.

v3 evaluated the ACCEL value once and overwrote DECEL with the ACCEL value (001:5662, 001:7203).
``ACCEL = INKEY * 1000`` took the next key from the buffer (001:9136-9160) and gave both rates the same value; copied
as ``: DECEL = INKEY * 1000`` the v4 program would read a second key (000:12135-12149) and decelerate at
another rate. The same holds for an input, an analogue reading, a position, TIME or the COMMS array,
which the controller or the host changes between two statements. v4 reads ACCEL back
(``v = ACCEL[axis]``, 000:6150-6152), so the DECEL write reads the value the ACCEL write set, axis
by axis in the order the ACCEL write gave them (001:1052-1109); where the default axes are not known,
a bare ``DECEL = ACCEL`` reads and writes the first of them, and ``;`` fills the rest alike.
"""

from __future__ import annotations

import pytest

from tests.migrate.helpers import flagged, migrated_twice, rewritten

CASES = [
    pytest.param("ACCEL.0 = INKEY * 1000\n", "ACCEL.0 = INKEY * 1000 : DECEL.0 = ACCEL.0\n", id="a key"),
    pytest.param(
        "ACCEL[0,1] = POS.0 * 2, 500\n", "ACCEL[0,1] = POS.0 * 2, 500 : DECEL[0,1] = ACCEL.0,ACCEL.1\n", id="two axes"
    ),
    pytest.param(
        "AXES[0,1]\nACCEL = COMMS(1);\n",
        "AXES[0,1]\nACCEL = COMMS(1); : DECEL = ACCEL.0,ACCEL.1\n",
        id="the default axes filled",
    ),
    pytest.param("AXES[0,1]\nACCEL = ,TIME\n", "AXES[0,1]\nACCEL = ,TIME : DECEL = ,ACCEL.1\n", id="a place skipped"),
    pytest.param("ACCEL[ax] = IN * 100\n", "ACCEL[ax] = IN * 100 : DECEL[ax] = ACCEL[ax]\n", id="a computed axis"),
    pytest.param("ACCELTIME.1 = INKEY\n", "ACCELTIME.1 = INKEY : DECELTIME.1 = ACCELTIME.1\n", id="ACCELTIME"),
    pytest.param(
        "IF a THEN AXES[0,1]\nACCEL = IN;\n",
        "IF a THEN AXES[0,1]\nACCEL = IN; : DECEL = ACCEL;\n",
        id="default axes not known, filled alike",
    ),
    pytest.param(
        "IF a THEN AXES[0,1]\nACCEL = IN\n", "IF a THEN AXES[0,1]\nACCEL = IN : DECEL = ACCEL\n", id="its first axis"
    ),
]


@pytest.mark.parametrize(("source", "expected"), CASES)
def test_decel_reads_back_the_accel_the_write_set(source: str, expected: str) -> None:
    assert rewritten("S-ACCEL", source) == expected


@pytest.mark.parametrize(("source", "expected"), CASES)
def test_the_migration_settles(source: str, expected: str) -> None:
    assert migrated_twice("S-ACCEL", source) == (expected, (), expected, ())


def test_a_value_of_plain_numbers_and_variables_is_still_copied() -> None:
    assert rewritten("S-ACCEL", "ACCEL.0 = rate * 2 + SIN(30)\n") == (
        "ACCEL.0 = rate * 2 + SIN(30) : DECEL.0 = rate * 2 + SIN(30)\n"
    )


@pytest.mark.parametrize("source", ["ACCEL[a,b] = INKEY, 5\n", "IF a THEN AXES[0,1]\nACCEL = INKEY, 5\n"])
def test_several_values_on_axes_not_known_are_left_for_a_person(source: str) -> None:
    assert flagged("S-ACCEL", source) == [
        "the value may change between two reads and the axes are not known: "
        "write DECEL from a variable holding the value"
    ]
