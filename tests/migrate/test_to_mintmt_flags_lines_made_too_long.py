"""A line ``--to mintmt`` takes past 255 characters, the most a controller's line holds (000:254-256), is
flagged for a person to split, as the v3 to v4 migration's X-CHECK flags one; a line already too long in
v4 is the checker's to report (W111), not the migration's."""

from __future__ import annotations

import pytest

from mintlang.migrate.mintmt import to_mintmt

# "a = " and 31 times "POS.0 + " and "0": 4 + 31 * 8 + 1 = 253 characters in v4; each POS.0 becomes
# POS(0), one character more: 253 + 31 = 284 in MintMT
TERMS = "POS.0 + " * 31
LONG = f"a = {TERMS}0"
REASON = "line of 284 characters in MintMT: the controller takes 255; split it"


def test_a_line_made_longer_than_255_characters_is_flagged_with_its_new_length() -> None:
    assert len(LONG) == 253
    result = to_mintmt(f"DIM a\n{LONG}\nPRINT a\n")
    assert [(item.rule, item.original_line, item.reason) for item in result.manual] == [("MT-LENGTH", 2, REASON)]
    assert result.text.splitlines()[1] == f"REM MIGRATE: MT-LENGTH: {REASON}"
    assert len(result.text.splitlines()[2]) == 284


@pytest.mark.parametrize(
    "line",
    [
        pytest.param(f"a = POS.0{' + a' * 60} + 10", id="made-255"),  # 9 + 240 + 5 = 254, then one more
        pytest.param(f"a = {'POS.0 + ' * 33}1", id="too-long-already"),  # 269 characters in v4 already
    ],
)
def test_a_line_within_the_limit_or_already_over_it_is_not_flagged(line: str) -> None:
    assert [item.rule for item in to_mintmt(f"DIM a\n{line}\n").manual] == []
