"""A marker is a line of the program: the controller downloads no line of more than 255 characters,
comments included (000:18455). A reason quoting a long line (a number of 5,000 digits in an error
message) is cut to fit, its end marked with ASCII dots."""

from __future__ import annotations

import pytest

from mintlang.migrate.context import MARKER_LINE, marker_text


@pytest.mark.parametrize(
    ("reason", "above", "expected"),
    [
        pytest.param("short", False, "REM MIGRATE: X-CHECK: short", id="kept"),
        # 13 + 9 = 22 characters before the reason: 233 of its characters fit exactly
        pytest.param("r" * 233, False, "REM MIGRATE: X-CHECK: " + "r" * 233, id="255-kept"),
        pytest.param("r" * 234, False, "REM MIGRATE: X-CHECK: " + "r" * 230 + "...", id="256-cut"),
        # "(line above) " takes 13 more
        pytest.param("9" * 5000, True, "REM MIGRATE: X-CHECK: (line above) " + "9" * 217 + "...", id="above-cut"),
    ],
)
def test_a_marker_is_at_most_255_characters(reason: str, above: bool, expected: str) -> None:
    text = marker_text("X-CHECK", reason, above=above)
    assert text == expected
    found = MARKER_LINE.match(text)
    assert found is not None and found["rule"] == "X-CHECK"
