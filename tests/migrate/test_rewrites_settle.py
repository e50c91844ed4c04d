"""A rule recognises what it wrote, however the v3 reader parses it: a second migration
changes nothing, and the engine never loops on a rule that keeps rewriting its own output.

DECELTIME and MASTERCHANNEL are v4 keywords the v3 reader takes for user names (v3 has
neither, v3:5635 ACCEL and v3:8163 FOLLOWAXIS are its words); the rules must still see
their own ``DECELTIME = 10`` and ``MASTERCHANNEL = 1`` as done.
"""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate

_SETTLE = [
    # S-ACCEL: v3 ACCELTIME also set the deceleration time (v3:5662); v4 wants DECELTIME too
    pytest.param("ACCELTIME = 10\n", "ACCELTIME = 10 : DECELTIME = 10\n", id="acceltime"),
    pytest.param("ACCELTIME = 10,20\n", "ACCELTIME = 10,20 : DECELTIME = 10,20\n", id="acceltime-two-axes"),
    pytest.param("ACCELTIME[0,1] = 5,6\n", "ACCELTIME[0,1] = 5,6 : DECELTIME[0,1] = 5,6\n", id="acceltime-axes"),
    pytest.param("acceltime.1 = 5\n", "acceltime.1 = 5 : deceltime.1 = 5\n", id="acceltime-lower-case"),
    pytest.param("ACCELTIME = 10;\n", "ACCELTIME = 10; : DECELTIME = 10;\n", id="acceltime-fill"),
    # S-MASTER: v3 FOLLOWAXIS named the master axis; v4 wants a source and a channel (v4:10773)
    pytest.param("FOLLOWAXIS = 1\n", "MASTERSOURCE = _msPOS : MASTERCHANNEL = 1\n", id="followaxis"),
]


@pytest.mark.parametrize(("source", "expected"), _SETTLE)
def test_the_rule_writes_once_and_then_leaves_its_output_alone(source: str, expected: str) -> None:
    first = migrate(source, only=["S-ACCEL", "S-MASTER"])
    assert first.text == expected
    assert migrate(first.text, only=["S-ACCEL", "S-MASTER"]).text == expected


@pytest.mark.parametrize(("source", "expected"), _SETTLE)
def test_all_rules_together_settle_on_a_second_run(source: str, expected: str) -> None:
    first = migrate(source)
    assert expected.rstrip("\n") in first.text
    assert migrate(first.text).text == first.text
