"""Rewrites that keep what a v3 line means but not its exact values, and what differs.

A mechanical rule can only keep v3's formula: M-TRIG keeps the thousandths v3's
SIN, COS and TAN returned, ``(SIN(x) * 1000)``, but v3 looked the value up in a
table of whole thousandths, about a tenth of a degree apart (001:2061-2069), where
v4 computes it (000:8676-8679). The migration report notes every line such a rule
changed, so that nobody meets the difference first in a run, and ``--verify``
tells the differences these lines cause from a divergence.
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType

TRIGONOMETRY = "M-TRIG"

DIFFERS: Mapping[str, str] = MappingProxyType(
    {
        TRIGONOMETRY: "values differ slightly: v3 looked SIN, COS and TAN up in a table of whole thousandths about "
        "0.1 degree apart, v4 computes them (SIN(45): v3 707, v4 707.1067); TAN 90 and TAN 270 are 8000000 "
        "in v3 only (001:2061-2069, 001:11975)",
    }
)
