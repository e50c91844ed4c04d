"""A keyword named alone as a statement is error 2005, and the message shows the use its access allows.

#2005 is a keyword neither read nor given a value (``SPEED : REM ...``, 000:18930-18933). SPEED is read
and written (000:16163-16168), so either is offered. IDLE is read only (its attributes table, 000:11732,
and error #2000 for a write, 000:18905-18907): offering ``IDLE = …`` sent the reader to that error. MOVEA
(000:14501) and ACCELTIME (#2002's example, 000:18916-18918) are write only, so reading is not offered.
"""

from __future__ import annotations

import pytest

import mintlang


def _message(source: str) -> str:
    (diagnostic,) = mintlang.check(source)
    assert diagnostic.code == "E2005"
    return diagnostic.message


def test_a_keyword_read_and_written_is_offered_both() -> None:
    assert _message("SPEED\n").endswith("SPEED must be read or given a value here (for example 'SPEED = …')")


@pytest.mark.parametrize("name", ["IDLE", "POSTARGET"])
def test_a_read_only_keyword_is_offered_a_read(name: str) -> None:
    message = _message(f"{name}\n")
    assert message.endswith(f"{name} is read only: read it here (for example 'PRINT {name}')")
    assert "= …" not in message


@pytest.mark.parametrize("name", ["MOVEA", "ACCELTIME", "WAIT"])
def test_a_write_only_keyword_is_offered_a_value(name: str) -> None:
    assert _message(f"{name}\n").endswith(f"{name} is write only: give it a value here (for example '{name} = …')")


def test_a_read_only_keyword_given_an_operand_is_not_offered_a_write() -> None:
    (diagnostic,) = mintlang.check("IDLE 1\n")
    assert diagnostic.code == "E2003"
    assert diagnostic.message.endswith("IDLE is read only and takes no value")
