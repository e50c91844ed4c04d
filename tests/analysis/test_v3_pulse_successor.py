"""v3's PULSE in v4 code: the v4 guide lists STEPPERIO as its replacement, but renaming is no fix.

v3 PULSE makes an axis follow the pulse timer input at a gear ratio (v3:11111-11153); v4's
STEPPERIO drives the pulse and direction outputs (its quick reference, v4:18181), and v4
follows an input with FOLLOW on a MASTERSOURCE (v4:3518-3527). mint-migrate marks PULSE for
review (X-PULSE: "not STEPPERIO"), while mint check offered "Replace with STEPPERIO".
"""

from __future__ import annotations

import pytest

import mintlang


@pytest.mark.parametrize(
    ("source", "code"),
    [
        pytest.param("PULSE.0 = 10\n", "E3007", id="with-an-axis"),
        pytest.param("PULSE = 1\n", "E3001", id="alone"),
    ],
)
def test_pulse_names_follow_and_offers_no_rename_to_stepperio(source: str, code: str) -> None:
    (found,) = mintlang.check(source)
    assert found.code == code
    assert "STEPPERIO" in found.message  # what the v4 guide says, as it says it
    assert "FOLLOW" in found.message
    assert "MASTERSOURCE" in found.message
    assert not any("STEPPERIO" in fix.title for fix in found.fixes)
