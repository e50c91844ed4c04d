"""The values MintMT's own keywords take, the same in ``mint check`` and ``mint-run``.

The notes print no attributes tables, so the ranges are ``mintlang/MINTMT.md``'s decisions, written once in the
keyword rows both tools read: TRIGGERMODE takes whole numbers (MT-10), MOVEBUFFERLOW a whole number of free places,
0 or more (MT-14), FEEDRATEOVERRIDE a percentage above 0 (MT-15), SUSPEND a whole number 0 or more (MT-16),
FEEDRATEMODE, a set of bits (004:278), a whole number 0 or more (MT-15), MOVEPULSEOUTX a whole number of
milliseconds, 1 or more (MT-22), and MOVEBUFFERSIZE v4's 2 to 100 moves (000:11053-11054), whole ones, as MintMT's
rows are (MT-1), and FEEDRATE what SPEED takes, the one slew speed written either way (MT-15), and CONTOURMODE v4's
modes 0, 1 and 3 (000:8653-8654), and OUTX(channel) what v4's OUT.channel takes (0 ≤ x < 4096 on NextMove PCI,
000:14911), being that output (004:148). Any other value is error 3, "Data specified out of range"
(000:18518-18521).
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Controller, ValueRange
from mintlang.keyworddb.supplements import attributes_for
from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import Limits, run_source
from mintlang.runtime.scenario import DrivesEnabled, Scenario

OUT_OF_RANGE = [
    pytest.param("TRIGGERMODE(0) = 0.5", id="TRIGGERMODE a fraction"),
    pytest.param("MOVEBUFFERLOW(0) = -1", id="MOVEBUFFERLOW below 0"),
    pytest.param("MOVEBUFFERLOW(0) = 2.5", id="MOVEBUFFERLOW a fraction"),
    pytest.param("FEEDRATEOVERRIDE(0) = 0", id="FEEDRATEOVERRIDE 0"),
    pytest.param("FEEDRATEOVERRIDE(0) = -10", id="FEEDRATEOVERRIDE below 0"),
    pytest.param("SUSPEND(0) = -1", id="SUSPEND below 0"),
    pytest.param("SUSPEND(0) = 0.5", id="SUSPEND a fraction"),
    pytest.param("MOVEPULSEOUTX(0,3) = 0", id="MOVEPULSEOUTX 0 ms"),
    pytest.param("MOVEPULSEOUTX(0,3) = 2.5", id="MOVEPULSEOUTX a fraction of a ms"),
    pytest.param("MOVEBUFFERSIZE(0) = 0", id="MOVEBUFFERSIZE below 2 places (000:11053-11054)"),
    pytest.param("MOVEBUFFERSIZE(0) = 101", id="MOVEBUFFERSIZE above 100 places (000:11053-11054)"),
    pytest.param("MOVEBUFFERSIZE([0,1]) = 1;", id="MOVEBUFFERSIZE of two axes below 2 places"),
    pytest.param("MOVEBUFFERSIZE(0) = 2.5", id="MOVEBUFFERSIZE a fraction of a place"),
    pytest.param("FEEDRATE(0) = -5", id="FEEDRATE below SPEED's 1 (000:16186-16230)"),
    pytest.param("CONTOURMODE(0) = 2", id="CONTOURMODE bit 1 without bit 0 (000:8653-8654)"),
    pytest.param("CONTOURMODE(0) = 7", id="CONTOURMODE above v4's 3"),
    pytest.param("CONTOURMODE(0) = 0.5", id="CONTOURMODE a fraction of a mode"),
    pytest.param("OUTX(1) = -1", id="OUTX below OUT's 0 (000:14911)"),
    pytest.param("OUTX(1) = 4096", id="OUTX at OUT's 4096 (000:14911)"),
    pytest.param("FEEDRATEMODE(0) = -1", id="FEEDRATEMODE below 0"),
    pytest.param("FEEDRATEMODE(0) = 0.5", id="FEEDRATEMODE a fraction of a bit"),
]

IN_RANGE = [
    pytest.param("TRIGGERMODE(0) = -2", id="TRIGGERMODE any whole number"),
    pytest.param("MOVEBUFFERLOW(0) = 0", id="MOVEBUFFERLOW 0"),
    pytest.param("FEEDRATEOVERRIDE(0) = 50.5", id="FEEDRATEOVERRIDE a fraction of a percent"),
    pytest.param("SUSPEND(0) = 1", id="SUSPEND 1"),
    pytest.param("MOVEPULSEOUTX(0,3) = 1", id="MOVEPULSEOUTX 1 ms"),
    pytest.param("MOVEBUFFERSIZE(0) = 2", id="MOVEBUFFERSIZE 2 places"),
    pytest.param("MOVEBUFFERSIZE([0,1]) = 100;", id="MOVEBUFFERSIZE of two axes 100 places"),
    pytest.param("FEEDRATE([0,1]) = 20;", id="FEEDRATE the note's 20 units/s (004:259)"),
    pytest.param("FEEDRATE(0) = 2.5", id="FEEDRATE a fraction, as SPEED takes"),
    pytest.param(
        "CONTOURMODE([0,1]) = _ctmCONTOUR_ON + _ctmVECTOR_ANGLE_ON;",
        id="CONTOURMODE the note's angle control (004:230)",
    ),
    pytest.param("OUTX(0) = _ON", id="OUTX the note's output on (004:148)"),
    pytest.param("FEEDRATEMODE([0,1]) = _frFEEDRATE;", id="FEEDRATEMODE the note's feedrate bit (004:258)"),
]


def _program(statement: str) -> str:
    return f"MOVEBUFFERSIZE(0) = 4\n{statement}\n"


def _checked(statement: str) -> list[str]:
    result = mintlang.check(_program(statement), dialect="mintmt", controller="nextmove-pci")
    return [diagnostic.code for diagnostic in result]


def _ran(statement: str) -> tuple[StopReason, int]:
    limits = Limits(until_ms=100, max_wall_s=60.0)
    enabled = Scenario(drives=(DrivesEnabled(),))  # an output move is loaded on an axis that can move
    result = run_source(
        _program(statement), dialect="mintmt", controller="nextmove-pci", scenario=enabled, limits=limits
    )
    return result.stop.reason, result.err


@pytest.mark.parametrize("statement", OUT_OF_RANGE)
def test_a_value_outside_the_range_is_error_3_in_the_check_and_the_run(statement: str) -> None:
    assert _checked(statement) == ["E0003"]
    assert _ran(statement) == (StopReason.ERROR, 3)


@pytest.mark.parametrize("statement", IN_RANGE)
def test_a_value_inside_the_range_passes_both(statement: str) -> None:
    assert _checked(statement) == []
    assert _ran(statement)[0] is not StopReason.ERROR


def _v4_range(name: str, controller: Controller) -> ValueRange | None:
    v4 = database().keywords.get(name)
    row = attributes_for(v4, controller, Dialect.V4) if v4 is not None else None
    return row.range if row is not None else None


REPLACED_V4_RANGES = [
    pytest.param(name, controller, id=f"{name} on {controller.value}")
    for name, keyword in database().mintmt_keywords.items()
    for row in keyword.attributes
    for controller in row.controllers
    if _v4_range(name, controller) is not None
]


@pytest.mark.parametrize(("name", "controller"), REPLACED_V4_RANGES)
def test_a_mintmt_entry_keeps_the_range_of_the_v4_keyword_it_replaces(name: str, controller: Controller) -> None:
    """MT-1: a MintMT entry written for the notes' brackets keeps v4's range, which mint-run still applies."""
    row = database().mintmt_keywords[name].attributes_for(controller)
    assert row is not None
    assert row.range == _v4_range(name, controller)
