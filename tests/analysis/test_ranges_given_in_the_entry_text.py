"""A range the attributes table writes as "see below" is read from the entry's text.

TERMINAL accepts a bit mask of the channels its table lists, ``_tmRS232`` = 0x01 up to
``_tmCAN2`` = 0x100 (000:16695-16706), so 511 sets every bit and 512 none it documents.
SERIALBAUD's valid rates are 9600, 19200 and 57600 (000:15859-15863). Its table ticks one column per
port and marks each port's default with a '*' (000:15856): the 9600 row ticks all five ports, the
NextMove ones as their default, so 57600, starred twice, is the default of the two ports left, MintDrive's
and ServoNode 51's RS232; NextMove has no port at 57600. On MintDrive the ranges
of DECEL, ERRORDECEL, HOMESPEED, JOG and SPEED depend on LOOPTIME (000:8893-8897, 9997-10001,
11616-11620, 12663-12667, 16181-16185); these keywords are scaled, so only a value no scale
factor can bring into any row's range is error 3 (000:18518).
"""

from __future__ import annotations

import pytest

import mintlang


def _codes(source: str, controller: str = "nextmove-pci") -> list[str]:
    return [d.code for d in mintlang.check(source, controller=controller)]


@pytest.mark.parametrize("value", ["_tmRS232 | _tmRS485", "511", "256"])
def test_a_terminal_mask_of_documented_bits_is_accepted(value: str) -> None:
    assert _codes(f"TERMINAL = {value}\n") == []


@pytest.mark.parametrize("value", ["512", "-1", "1024"])
def test_a_terminal_mask_with_an_undocumented_bit_is_error_3(value: str) -> None:
    assert _codes(f"TERMINAL = {value}\n") == ["E0003"]


@pytest.mark.parametrize("rate", ["9600", "19200", "57600"])
def test_a_listed_baud_rate_is_accepted(rate: str) -> None:
    assert _codes(f"SERIALBAUD._tmRS232 = {rate}\n", "mintdrive") == []


@pytest.mark.parametrize("rate", ["4800", "38400", "115200", "9601"])
def test_an_unlisted_baud_rate_is_error_3(rate: str) -> None:
    assert _codes(f"SERIALBAUD._tmRS232 = {rate}\n", "mintdrive") == ["E0003"]


@pytest.mark.parametrize("terminal", ["_tmRS232", "_tmRS485"])
def test_nextmove_takes_no_port_at_57600(terminal: str) -> None:
    assert _codes(f"SERIALBAUD.{terminal} = 57600\n", "nextmove-bx") == ["E0003"]
    assert _codes(f"SERIALBAUD.{terminal} = 9600\n", "nextmove-bx") == []
    (diagnostic,) = mintlang.check(f"SERIALBAUD.{terminal} = 57600\n", controller="nextmove-bx")
    assert "(9600, 19200)" in diagnostic.message


def test_servonode_takes_its_default_rate() -> None:
    assert _codes("SERIALBAUD._tmRS232 = 57600\n", "servonode51") == []


def test_the_baud_rate_message_names_the_listed_rates() -> None:
    (diagnostic,) = mintlang.check("SERIALBAUD._tmRS485 = 38400\n", controller="mintdrive")
    assert "9600, 19200, 57600" in diagnostic.message


@pytest.mark.parametrize(
    ("keyword", "inside", "outside"),
    [
        ("DECEL", "1", "0"),  # 977 ≤ x at the slowest LOOPTIME: positive
        ("ERRORDECEL", "1", "0"),
        ("HOMESPEED", "1", "0"),  # 4 ≤ x: positive
        ("SPEED", "0", "-1"),  # 0 ≤ x
        ("JOG", "-5", None),  # -8000000 ≤ x ≤ 8000000: either sign
    ],
)
def test_mintdrive_looptime_ranges_bound_the_sign(keyword: str, inside: str, outside: str | None) -> None:
    assert _codes(f"{keyword}.0 = {inside}\n", "mintdrive") == []
    if outside is not None:
        assert _codes(f"{keyword}.0 = {outside}\n", "mintdrive") == ["E0003"]


def test_a_zero_homing_speed_is_in_range_on_nextmove_only() -> None:
    assert _codes("HOMESPEED.0 = 0\n") == []  # NextMove prints 0 ≤ x ≤ 8388607.0 (000:11609)
    assert _codes("HOMESPEED.0 = 0\n", "mintdrive") == ["E0003"]
