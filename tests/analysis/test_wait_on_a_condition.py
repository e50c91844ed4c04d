"""WAIT written as if it waited on a condition says how to write both.

WAIT suspends the program for a number of milliseconds, written 'WAIT = <expression>'
(000:17314-17324); to wait until a condition holds the language has PAUSE (000:15013-15030).
'WAIT IDLE.0' is a syntax error, and its message names both forms.
"""

from __future__ import annotations

import pytest

import mintlang


@pytest.mark.parametrize("source", ["WAIT IDLE.0\n", "WT IN1\n", "WAIT 100\n"])
def test_wait_without_equals_is_a_syntax_error_naming_wait_and_pause(source: str) -> None:
    (error,) = mintlang.check(source)
    assert error.code == "E2003"
    assert "'WAIT = 100'" in error.message and "PAUSE" in error.message


def test_wait_with_a_time_is_accepted() -> None:
    assert mintlang.check("WAIT = 250\n") == []
