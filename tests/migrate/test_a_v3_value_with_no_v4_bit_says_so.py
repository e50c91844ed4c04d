"""S-MODE and S-ERROR: a test of a v3 value no v4 bit stands for says which value it is and that it has none.

v3 ERROR 13 is a digital output fault, SmartMove only (001:5003), and MODE 11 a MOVECAM cam segment, 17 the
MINT/3.28 joystick (001:10052, 001:10058); v4 AXISERROR and AXISMODE have no bit for them (000:6967-7040,
000:7139-7171). MODE 5 is pulse following (001:10046), which v4 does with FOLLOW once the pulse input is
wired as a master (X-PULSE). The item said to rewrite the test as a bit test, of a bit that is not there.
"""

from __future__ import annotations

import pytest

from tests.migrate.helpers import flagged


@pytest.mark.parametrize(
    ("rule", "source", "reason"),
    [
        (
            "S-ERROR",
            'IF ERROR = 13 THEN PRINT "output fault"\n',
            "v3 ERROR 13 (digital output fault, SmartMove only) has no AXISERROR bit: rewrite this test by hand",
        ),
        (
            "S-MODE",
            "IF MODE.1 = 11 THEN x = 1\n",
            "v3 MODE 11 (MOVECAM cam segment) has no AXISMODE bit: rewrite this test by hand",
        ),
        (
            "S-MODE",
            "PAUSE MODE <> 17\n",
            "v3 MODE 17 (joystick, MINT/3.28 only) has no AXISMODE bit: rewrite this test by hand",
        ),
        (
            "S-MODE",
            "IF MODE = _pulse THEN x = 1\n",
            "v3 MODE 5 (pulse following) has no AXISMODE bit: once X-PULSE makes it a FOLLOW, test _mdFOLLOW",
        ),
    ],
)
def test_a_value_without_a_bit_is_named(rule: str, source: str, reason: str) -> None:
    assert flagged(rule, source) == [reason]


def test_other_uses_keep_the_bit_test_advice() -> None:
    assert flagged("S-MODE", "IF MODE > 2 THEN x = 1\n") == [
        "MODE was a value, AXISMODE is a bit pattern: rewrite this use as a bit test"
    ]
