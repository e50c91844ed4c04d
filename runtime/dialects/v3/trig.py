"""Mint v3 ``SIN``, ``COS`` and ``TAN``: degrees in, the value times 1000 out, from a 90 degree table.

The guide: the angle is 0 to 360 degrees; "lookup is performed on a 90 degree
table with 1000 elements", accurate to about a tenth of a degree; SIN and COS
return -1000..1000, TAN -1000000..1000000 and 8000000 for TAN 90 (001:2061-2069,
7039-7051, 11765-11779, 11969-11983). It does not give the table, so this model is
the simplest one that reproduces every value the guide prints (V3-3): element i
holds ``floor(1000 * sin(i * 0.09 degrees))``, an angle looks up element
``ceil(angle / 0.09)`` of its quadrant, ``COS a`` is ``SIN (90 - a)`` folded into
0..360, and ``TAN`` is ``SIN * 1000 / COS`` of the first-quadrant angle, truncated,
with the sign of its quadrant; TAN 270 is 8000000 like TAN 90. It gives ``SIN 30`` 500, ``COS(30)`` 866, ``SIN(245)``
-906, ``TAN(45)`` 1000 and ``TAN(80)`` 5622, as printed; other angles may differ
from a controller's table by the tenth of a degree the guide allows. An angle
outside 0..360 is not simulated.
"""

from __future__ import annotations

import math

from mintlang.runtime.errors import NotSimulated

ENTRIES = 1000  # elements of the 90 degree table
TAN_90 = 8_000_000.0
_TABLE = tuple(math.floor(1000 * math.sin(math.radians(index * 90 / ENTRIES))) for index in range(ENTRIES + 1))


def _first_quadrant(degrees: float) -> int:
    """The table value for an angle of 0 to 90 degrees."""
    return _TABLE[math.ceil(degrees * ENTRIES / 90)]


def _checked(name: str, degrees: float) -> float:
    if not 0 <= degrees <= 360:
        raise NotSimulated(name, "an angle outside 0 to 360 degrees")
    return degrees


def _folded(degrees: float) -> tuple[float, int]:
    """The first-quadrant angle of ``degrees`` (0..360) and the sign SIN has there."""
    if degrees <= 90:
        return degrees, 1
    if degrees <= 180:
        return 180 - degrees, 1
    if degrees <= 270:
        return degrees - 180, -1
    return 360 - degrees, -1


def sine(degrees: float) -> float:
    angle, sign = _folded(_checked("SIN", degrees))
    return float(sign * _first_quadrant(angle))


def cosine(degrees: float) -> float:
    angle = 90 - _checked("COS", degrees)
    return sine(angle + 360 if angle < 0 else angle)


def tangent(degrees: float) -> float:
    """TAN 90 (and TAN 270, where the table's cosine is 0 too) is 8000000."""
    angle, _ = _folded(_checked("TAN", degrees))
    cosine_value = _first_quadrant(90 - angle)
    if cosine_value == 0:
        return TAN_90
    sign = 1 if degrees < 90 or 180 <= degrees < 270 else -1
    return float(sign * math.trunc(_first_quadrant(angle) * 1000 / cosine_value))
