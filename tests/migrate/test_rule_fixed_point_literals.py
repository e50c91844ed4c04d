"""X-NUM reads a literal as Mint v3 held it: three decimal places, rounded to the nearest 256th.

The v3 guide says a number is rounded to the nearest part in 256: ``PRINT 1.002`` shows 1.003,
the value held being 257/256 = 1.00390625 (v3:1161-1170); its worked 0.15 comes to 38.4/256,
so 38/256 = 0.1484375, shown as 0.148 (v3:1171-1181). Truncating to 1/256 steps would hold
1.002 as 1.000 and 2.3 as 2.296875; the nearest step gives 1.0039 and 2.30078125.
"""

from __future__ import annotations

import pytest

from mintlang.migrate.rules.numbers import v3_value
from tests.migrate.helpers import flagged


@pytest.mark.parametrize(
    ("literal", "held"),
    [
        pytest.param(1.002, 257 / 256, id="guide-1.002"),
        pytest.param(0.15, 38 / 256, id="guide-0.15"),
        pytest.param(2.3, 2 + 77 / 256, id="0.3-is-76.8-steps"),
        pytest.param(0.004, 1 / 256, id="1.024-steps"),
        pytest.param(0.5, 0.5, id="dyadic"),
    ],
)
def test_the_value_v3_held(literal: float, held: float) -> None:
    assert v3_value(literal) == held


def test_the_guide_s_1_002_is_reported_with_the_value_it_held_and_showed() -> None:
    # v3:1161-1171: PRINT 1.002 displays 1.003, the nearest part in 256 being 257/256
    assert flagged("X-NUM", "PRINT 1.002\n") == [
        "1.002 was 257/256 in v3 (1/256 fixed point; PRINT shows 1.003), floating point in v4"
    ]


def test_a_literal_beyond_v3_s_range_is_no_fixed_point_question() -> None:
    assert flagged("X-NUM", "a = 9000000.5\n") == []


def test_a_literal_held_just_below_what_is_written_shows_one_thousandth_less() -> None:
    # 0.004 is held as 1/256 = 0.00390625 and PRINT cuts it to three places (v3:1161-1170), as 1.003 for 1.002
    assert flagged("X-NUM", "PRINT 0.004\n") == [
        "0.004 was 1/256 in v3 (1/256 fixed point; PRINT shows 0.003), floating point in v4"
    ]
