"""The per-LOOPTIME ranges hold on every controller the sentence above their table names.

ACCEL, DECEL, ERRORDECEL, HOMESPEED and JOG say "On MintDrive and ServoNode 51 the range depends
upon ... LOOPTIME" (000:6169, 8891, 9995, 11614, 12661); the rows are 500: 15625 ≤ x, 1000:
3907 ≤ x and 2000: 977 ≤ x for the rates (000:6172-6175), 2000: 4 ≤ x for HOMESPEED
(000:11620) and ±8000000 at 500 for JOG (000:12664). Whatever the LOOPTIME, a rate of 100
counts/s² is below every row, so it is error 3 on both controllers; 977 is in range at 2000.
ACCEL's own table has one "All" row printing NextMove's 0.0 < x (000:6164-6167), where 100
stays a valid rate. SPEED's sentence names MintDrive alone (000:16179).
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate

_BELOW_EVERY_ROW = [("ACCEL", "100"), ("DECEL", "100"), ("ERRORDECEL", "100"), ("HOMESPEED", "1"), ("JOG", "9000000")]


@pytest.mark.parametrize("controller", ["mintdrive", "servonode51"])
@pytest.mark.parametrize(("keyword", "value"), _BELOW_EVERY_ROW)
def test_a_value_outside_every_looptime_row_is_error_3(controller: str, keyword: str, value: str) -> None:
    result = simulate(f"{keyword}.0 = {value}\n", controller=controller)
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 3, 1)


@pytest.mark.parametrize("controller", ["mintdrive", "servonode51"])
@pytest.mark.parametrize("keyword", ["ACCEL", "DECEL"])
def test_a_rate_inside_the_slowest_looptime_row_is_taken(controller: str, keyword: str) -> None:
    result = simulate(f"{keyword}.0 = 977\nPRINT {keyword}.0\n", controller=controller)
    assert (result.stop.reason, result.terminal) == (StopReason.END, "977\n")


def test_an_acceleration_of_100_stays_valid_on_nextmove() -> None:
    result = simulate("ACCEL.0 = 100\nPRINT ACCEL.0\n", controller="nextmove-pci")
    assert (result.stop.reason, result.terminal) == (StopReason.END, "100\n")


@pytest.mark.parametrize("keyword", ["DECEL", "ERRORDECEL", "HOMESPEED"])
def test_mint_check_refuses_a_rate_of_0_on_servonode_as_on_mintdrive(keyword: str) -> None:
    # scaled: no scale factor brings 0 into a range whose every row starts above 0 (000:18518)
    for controller in ("mintdrive", "servonode51"):
        assert [d.code for d in mintlang.check(f"{keyword}.0 = 0\n", controller=controller)] == ["E0003"]
