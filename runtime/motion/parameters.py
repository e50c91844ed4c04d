"""Axis parameters: defaults, ranges and scaling (spec MP-1..MP-3, the DEFAULT table [000:9008-9058]).

Scaled parameters are stored in encoder counts, so changing ``SCALE`` changes
what reads back (``SPEED`` of 20000 counts/s reads 200 after ``SCALE = 100``)
while the motion itself is unchanged (MP-1 RC). Ranges come from the keyword
database's attributes table for the target controller; a value outside raises
error 3, as the controller does.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace
from functools import cache
from types import MappingProxyType

from mintlang.keyworddb.model import Controller
from mintlang.keyworddb.supplements import POSITIVE_ONLY
from mintlang.runtime.ranges import Bounds, table_bounds, table_default

# Servo-axis defaults from the DEFAULT table, in counts (SCALE 1). Where the keyword entry and the
# table disagree the table wins (HOMESPEED 40000, HOMEINPUT -1, MASTERDISTANCE 1000: spec HM-2, FG-2).
DEFAULTS: Mapping[str, float] = MappingProxyType(
    {
        "ACCEL": 300_000.0,
        "DECEL": 300_000.0,
        "ERRORDECEL": 300_000.0,
        "SPEED": 20_000.0,
        "SRAMP": 0.0,
        "SCALE": 1.0,
        "HOMESPEED": 40_000.0,
        "HOMEBACKOFF": 10.0,
        "HOMEINPUT": -1.0,
        "FOLERRORFATAL": 1000.0,
        "FOLERRORMODE": 1.0,
        "IDLEPOS": 1000.0,
        "IDLEVEL": 0.0,
        "KPROP": 0.0,
        "KINT": 0.0,
        "KINTLIMIT": 100.0,
        "KINTMODE": 1.0,
        "KDERIV": 0.0,
        "KVEL": 0.0,
        "KVELFF": 0.0,
        "KACCEL": 0.0,
        "DACLIMITMAX": 100.0,
        "SOFTLIMITFORWARD": 8_388_607.0,
        "SOFTLIMITREVERSE": -8_388_607.0,
        "SOFTLIMITMODE": 0.0,
        "LIMITFORWARDINPUT": -1.0,
        "LIMITREVERSEINPUT": -1.0,
        "LIMITMODE": 1.0,
        "ERRORINPUT": -1.0,
        "ERRORINPUTMODE": 1.0,
        "STOPINPUT": -1.0,
        "STOPINPUTMODE": 1.0,
        "MOVEBUFFERSIZE": 2.0,
        "CONFIG": 1.0,
        "DRIVEENABLEOUTPUT": -1.0,
        "ENCODERWRAP": 0.0,  # counts; 0 is no wrap (000:9024, 9825)
        "ENCODERSCALE": 1.0,  # counts per ENCODER unit (000:9023, 9735-9737)
        "ENCODERPRESCALE": 1.0,  # encoder edges per count the controller sees (000:9022, 9682-9694)
    }
)
SCALED: frozenset[str] = frozenset(
    {
        "ACCEL",
        "DECEL",
        "ERRORDECEL",
        "SPEED",
        "HOMESPEED",
        "FOLERRORFATAL",
        "IDLEPOS",
        "IDLEVEL",
        "SOFTLIMITFORWARD",
        "SOFTLIMITREVERSE",
    }
)
GAINS: frozenset[str] = frozenset(
    {"KPROP", "KINT", "KINTLIMIT", "KINTMODE", "KDERIV", "KVEL", "KVELFF", "KACCEL", "DACLIMITMAX"}
)


@cache
def power_up(controller: Controller) -> Mapping[str, float]:
    """An axis's parameters at power-up (and after DEFAULT) on ``controller``: the DEFAULT table's, with
    CONFIG as the controller's row of its attributes table gives it: MintDrive 0, ServoNode 51 1
    (000:8421-8424); NextMove's "1 and 2" (servo and stepper axes) leaves the reference's servo axes at 1."""
    config = table_default("CONFIG", controller)
    return DEFAULTS if config is None else MappingProxyType({**DEFAULTS, "CONFIG": config})


def bounds(keyword: str, controller: Controller) -> Bounds:
    """The accepted values of ``keyword`` on ``controller`` (unbounded when nothing gives any).

    ``SCALE`` takes only a positive value (000:532-537) on every controller, though NextMove's
    table prints 0 <= x (000:15783) and ServoNode's none: error 3 then says "more than 0", not
    the "0 to" a user would try next. ``ENCODERSCALE`` too (NextMove's table: 0.0 <= x, 000:9727):
    it divides the counts into ENCODER's units as SCALE divides them into POS's (000:9731-9735).
    """
    table = table_bounds(keyword, controller)
    if keyword in POSITIVE_ONLY and (table.minimum is None or table.minimum <= 0):
        return replace(table, minimum=0.0, exclusive_minimum=True)
    return table
