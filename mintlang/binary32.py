"""Mint v4's numbers: an 8-bit exponent and a 24-bit mantissa (000:714-716), IEEE binary32 as simulated.

The checker works a value out as the controller holds it where that decides a finding: a divisor
that rounds to zero, a literal or a result too large to hold. mint-run's EXP and POW are these
functions too, so both tools find the same results without a value.
"""

from __future__ import annotations

import math
import struct

_FORMAT = struct.Struct("<f")


def rounded(value: float) -> float:
    """``value`` rounded to the nearest binary32 number; OverflowError when it is too large for one."""
    return _FORMAT.unpack(_FORMAT.pack(value))[0]


def holds(value: float) -> bool:
    """Whether ``value`` is a number the controller can hold: finite, and within binary32's range once rounded."""
    try:
        return math.isfinite(rounded(value))
    except OverflowError:
        return False


def exp(x: float) -> float:
    """``EXP(x)`` as the controller holds it; OverflowError when it is too large for a number."""
    return rounded(math.exp(x))


def power(x: float, y: float) -> float:
    """``POW(x, y)`` as the controller holds it; OverflowError when it is too large for a number,
    ZeroDivisionError for 0 to a negative power (1 / 0 ** -y), ValueError for a negative number to a
    fraction, which has no real value."""
    if x == 0 and y < 0:
        raise ZeroDivisionError("0 to a negative power")
    return rounded(math.pow(x, y))


def shortest(value: float) -> str:
    """``value`` as a person reads it: the shortest decimal that reads back as the same value, rounded to binary32
    where it is one (0.1, not 0.100000001), whole numbers without a point, every digit kept (8388607.5, not
    8388608; 16777216, not 1.67772e+07)."""
    if not math.isfinite(value):
        return str(value)
    if value.is_integer() and abs(value) < 1e15:
        return str(int(value))
    single = abs(value) < 3.4e38 and rounded(value) == value
    for digits in range(1, 18):
        text = f"{value:.{digits}g}"
        if float(text) == value or (single and rounded(float(text)) == value):
            return text
    return repr(value)
