"""Mint v3 axis parameters: their v3 names and power-up values, over the v4 axis's parameters (their ranges:
``mintlang.keyworddb.v3_ranges``)."""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType

from mintlang.keyworddb.v3_ranges import AXIS_PARAMETERS
from mintlang.runtime.dialects.v3.controllers import HOME_INPUT, LIMIT_INPUT, STOP_INPUT
from mintlang.runtime.motion.axis import Axis
from mintlang.runtime.motion.parameters import DEFAULTS

POWER_UP: Mapping[str, float] = MappingProxyType(
    {
        "SPEED": 40_000.0,
        "ACCEL": 300_000.0,
        "DECEL": 300_000.0,
        "ERRORDECEL": 300_000.0,  # the stop input ramps down at DECEL (001:7219)
        "HOMESPEED": 40_000.0,
        "HOMEBACKOFF": 10.0,
        "FOLERRORFATAL": 16_000.0,
        "IDLEPOS": 16_000.0,
        "DACLIMITMAX": 100.0,
    }
)
"""v3's power-up values of the v4 parameters, in counts (001:11797, 5649, 7192, 8632, 6061, 9989, 8741, 7059);
the others are v4's."""

RENAMED: Mapping[str, str] = MappingProxyType(
    {
        "GAIN": "KPROP",
        "KINTRANGE": "KINTLIMIT",
        "HMSPEED": "HOMESPEED",
        "BACKOFF": "HOMEBACKOFF",
        "MFOLERR": "FOLERRORFATAL",
        "CURRLIMIT": "DACLIMITMAX",
        "IDLE": "IDLEPOS",
    }
)
"""v3 names of v4 axis parameters (001 chapter 10; spec M-REN); IDLE only when written (001:8762-8770)."""

CHECKED_IN_V3 = frozenset(RENAMED.get(name, name) for name in AXIS_PARAMETERS) & DEFAULTS.keys()
"""The v4 parameters whose v3 range replaces the v4 machine's."""


def power_up(axis: Axis) -> None:
    """The v4 parameters of a v3 axis at power-up (and after DEFAULT): v3's values and its dedicated inputs, the
    limit input watched in both directions (001:4600)."""
    limit = float(LIMIT_INPUT + axis.number)
    inputs = {"HOMEINPUT": float(HOME_INPUT + axis.number), "STOPINPUT": float(STOP_INPUT)}
    for name, value in {**POWER_UP, **inputs, "LIMITFORWARDINPUT": limit, "LIMITREVERSEINPUT": limit}.items():
        axis.set(name, value)
