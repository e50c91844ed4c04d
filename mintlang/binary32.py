"""Mint v4's numbers: an 8-bit exponent and a 24-bit mantissa (000:714-716), IEEE binary32 as simulated.

The checker works a value out as the controller holds it where that decides a finding: a divisor
that rounds to zero, a literal too large to hold.
"""

from __future__ import annotations

import struct

_FORMAT = struct.Struct("<f")


def rounded(value: float) -> float:
    """``value`` rounded to the nearest binary32 number; OverflowError when it is too large for one."""
    return _FORMAT.unpack(_FORMAT.pack(value))[0]
