"""v3's PAUSE with no condition waits for a key (001:2211); v4's PAUSE needs one (error 2005), and PAUSE INKEY
waits for any key in both guides (001:2217-2223, 000:1689-1690): M-PAUSEKEY writes it so."""

from __future__ import annotations

import pytest

import mintlang
from mintlang.migrate import migrate
from tests.migrate.helpers import rewritten


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        pytest.param("PAUSE\n", "PAUSE INKEY\n", id="alone"),
        pytest.param("PRINT 1 : PAUSE : PRINT 2\n", "PRINT 1 : PAUSE INKEY : PRINT 2\n", id="between-statements"),
        pytest.param("pause\n", "pause inkey\n", id="in-its-case"),
        pytest.param("PAUSE IN1\n", "PAUSE IN1\n", id="a-condition-stays"),
    ],
)
def test_a_pause_with_no_condition_becomes_pause_inkey(source: str, expected: str) -> None:
    assert rewritten("M-PAUSEKEY", source) == expected


def test_the_migrated_pause_is_valid_mint_v4() -> None:
    result = migrate('PRINT "press a key"\nPAUSE\nPRINT "go"\n')
    assert result.text == 'PRINT "press a key"\nPAUSE INKEY\nPRINT "go"\n'
    assert result.manual == ()


def test_mint_check_takes_a_bare_pause_in_v3_only() -> None:
    assert [d.code for d in mintlang.check("PAUSE\n", dialect="v3")] == []
    assert [d.code for d in mintlang.check("PAUSE\n")] == ["E2005"]
