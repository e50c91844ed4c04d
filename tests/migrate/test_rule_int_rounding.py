"""X-NUM flags INT of a value that can be negative: v3 INT rounds down, v4 INT rounds toward zero.

v3 (001:9244-9278): INT "will effectively round down", and rounding to the nearest integer is
INT(x + .5) for any sign; v4 (000:12565-12568): INT makes "the number closer to zero", so the nearest
integer takes - 0.5 for a negative number. INT(-2.5) is -3 in v3 and -2 in v4. The migration spec
(§10, INT row) asks for a flag "when negative values are possible".
"""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate
from mintlang.migrate.verification import Verdict, verify
from tests.migrate.helpers import flagged

REASON = "INT of a value that can be negative: v3 rounded it down (INT(-2.5) = -3), v4 toward zero (-2)"


@pytest.mark.parametrize(
    "source",
    [
        "PRINT INT(-2.5)\n",
        "? INT POS\n",  # v3:9267
        "a = INT(POS + .5)\n",  # v3:9274
        "a = INT(b / 3)\n",
        "a = INT(2 - b)\n",
    ],
)
def test_int_of_a_value_that_can_be_negative_is_flagged(source: str) -> None:
    assert flagged("X-NUM", source) == [REASON]


@pytest.mark.parametrize(
    "source",
    [
        "PRINT INT(12)\n",
        "a = INT(ABS(b) / 2)\n",
        "a = INT((3 + 4) * 2)\n",
    ],
)
def test_int_of_a_value_that_cannot_be_negative_is_left_alone(source: str) -> None:
    assert flagged("X-NUM", source) == []


def test_the_int_m_scale_writes_is_no_question_scale_is_positive() -> None:
    # M-SCALE writes SCALE = INT(e) (spec M-SCALE); SCALE takes 1 to 3200 in v3 (v3:11592), 0 or more in v4
    result = migrate("SCALE = b / 2\n")
    assert "SCALE = INT(b / 2)\n" in result.text
    assert "X-NUM" not in {item.rule for item in result.manual}


def test_the_flagged_int_is_the_divergence_verify_finds() -> None:
    # the v3 run prints -3, the v4 run -2: the statement is flagged, so the difference is accounted for
    result = migrate("PRINT INT(-2.5)\n")
    assert [item.rule for item in result.manual] == ["X-NUM"]
    assert verify(result, until_ms=10).verdict is Verdict.DIVERGES
