"""SCALE takes only a positive value, and the error says so rather than offering 0.

The guide's range check example: ``SCALE = -1`` is out of range "because SCALE only accepts a
positive value" (000:532-537), and ``SCALE = -3`` is error 3 (000:4600-4606). NextMove's
attributes table prints 0 <= x <= 8388607.0 and MintDrive's 1 <= x <= 65535 (000:15783-15784):
the upper bounds stand, and 0 is refused on NextMove as a negative value is. ServoNode's table gives
no range, and the guide's rule holds there too.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate


@pytest.mark.parametrize("value", ["0", "-3", "8388608"])
def test_scale_out_of_range_on_nextmove_is_error_3_saying_more_than_0(value: str) -> None:
    result = simulate(f"SCALE.0 = {value}\n")
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 3, 1)
    assert "it takes more than 0 and at most 8388607" in result.stop.message


def test_a_fractional_scale_on_nextmove_is_taken() -> None:
    result = simulate("SCALE.0 = 0.5\nPRINT SCALE.0\n")
    assert (result.stop.reason, result.terminal) == (StopReason.END, "0.5\n")


def test_scale_0_on_mintdrive_is_error_3_saying_1_to_65535() -> None:
    result = simulate("SCALE.0 = 0\n", controller="mintdrive")
    assert (result.stop.reason, result.err) == (StopReason.ERROR, 3)
    assert "it takes 1 to 65535" in result.stop.message


@pytest.mark.parametrize("value", ["0", "-3"])
def test_scale_not_positive_on_servonode_is_error_3_saying_more_than_0(value: str) -> None:
    result = simulate(f"SCALE.0 = {value}\n", controller="servonode51")
    assert (result.stop.reason, result.err) == (StopReason.ERROR, 3)
    assert "it takes more than 0)" in result.stop.message


@pytest.mark.parametrize("keyword", ["SCALE.0", "ENCODERSCALE.0"])
def test_mint_check_refuses_a_scale_not_positive_on_servonode_too(keyword: str) -> None:
    # the checker gives the run's error on the same line, though the table it reads prints no range there
    (diagnostic,) = mintlang.check(f"{keyword} = -3\n", controller="servonode51")
    assert diagnostic.code == "E0003" and "takes only a positive value" in diagnostic.message
