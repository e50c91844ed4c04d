"""How Mint v3 prints numbers: three decimals, cut, not rounded (001:1161-1181, 001:6209-6239).

A v3 number has a resolution of 1/256, about 0.004, and the guide prints it to
three places: ``PRINT 1.002`` shows ``1.003`` (the value held is 1.00390625) and
``PRINT 0.15`` shows ``0.148`` (0.1484375), so the digits are cut, not rounded.
Trailing zeros and a bare point are dropped as in v4 (V3-4: the guide shows no
number with them). ``USING`` follows the same rules as v4 (001:11002-11045), and
``BINARY`` prints a byte as eight binary digits (001:2750-2762).
"""

from __future__ import annotations

import math

from mintlang.runtime import printing
from mintlang.runtime.errors import NotSimulated

PLACES = 3


def format_number(value: float) -> str:
    """``PRINT x``: three places, cut toward zero, trailing zeros dropped; never ``-0``."""
    return printing.format_number(value, PLACES)


def format_binary(value: float) -> str:
    """``BINARY x``: 8 binary digits, a negative number in two's complement (``12`` -> ``00001100``).

    "All numbers are stripped of their fractional part", as ``INT`` strips it: rounding down. The guide
    prints "up to 8 bits"; what it makes of a number outside -128..255 is not said.
    """
    whole = math.floor(value)
    if not -128 <= whole <= 255:
        raise NotSimulated("BINARY", "a number outside -128 to 255")
    return f"{whole & 0xFF:08b}"
