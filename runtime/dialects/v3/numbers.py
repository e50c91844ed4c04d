"""Mint v3 numbers: four-byte scaled integers, 24 integer bits and 8 fraction bits (001:1157-1181).

Every value is a whole number of 256ths between -8388608 and 8388607.996. A
value is held here as the Python float of that fraction, which is exact; the
arithmetic works on the integer count of 256ths. A written number is rounded to
the nearest 256th, as the guide's ``PRINT 1.002`` printing ``1.003`` requires
(001:1161-1170). Where the guide says nothing the choices are recorded in
``runtime/BEHAVIOUR.md`` (V3-2): products and quotients drop the bits below 1/256
toward zero, as its worked conversion ``INT(150 * 256 / 1000)`` does
(001:1171-1181); bitwise operators work on the 32-bit pattern. A result outside
the range, a division by zero, and ``~`` of anything but a byte are not
simulated: the guide does not say what they do.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from types import MappingProxyType

from mintlang.runtime.errors import NotSimulated
from mintlang.runtime.numbers import logical_not, spelled

STEPS = 256  # parts of one in a v3 number
_LOWEST = -(1 << 31)
_HIGHEST = (1 << 31) - 1


def _checked(raw: int, what: str) -> float:
    if not _LOWEST <= raw <= _HIGHEST:
        raise NotSimulated(what, "a result outside -8388608 to 8388607.996")
    return raw / STEPS


def raw(value: float) -> int:
    """The count of 256ths a v3 value holds (its 32-bit pattern, read as a signed integer)."""
    return int(value * STEPS)


def fixed(value: float) -> float:
    """A number as v3 holds it: the nearest 256th, halves away from zero (001:1161-1170)."""
    scaled = abs(value) * STEPS
    if math.isinf(scaled) or math.isnan(scaled):
        raise NotSimulated("number", "a result outside -8388608 to 8388607.996")
    nearest = math.floor(scaled + 0.5)
    return _checked(-nearest if value < 0 else nearest, "number")


def add(a: float, b: float) -> float:
    return _checked(raw(a) + raw(b), "+")


def subtract(a: float, b: float) -> float:
    return _checked(raw(a) - raw(b), "-")


def _toward_zero(numerator: int, denominator: int) -> int:
    quotient = abs(numerator) // abs(denominator)
    return quotient if (numerator < 0) == (denominator < 0) else -quotient


def multiply(a: float, b: float) -> float:
    return _checked(_toward_zero(raw(a) * raw(b), STEPS), "*")


def divide(a: float, b: float) -> float:
    if b == 0:
        raise NotSimulated("/", "division by zero")
    return _checked(_toward_zero(raw(a) * STEPS, raw(b)), "/")


def modulo(a: float, b: float) -> float:
    """``MOD``/``%``: the remainder of the quotient taken toward zero, so the sign follows the dividend."""
    if b == 0:
        raise NotSimulated("MOD", "division by zero")
    left, right = raw(a), raw(b)
    return _checked(left - _toward_zero(left, right) * right, "MOD")


def _signed32(pattern: int) -> int:
    pattern &= 0xFFFFFFFF
    return pattern - (1 << 32) if pattern >> 31 else pattern


def bit_and(a: float, b: float) -> float:
    """``AND``/``&``: bitwise, so ``5 & 6`` is 4 (001:2021-2031); on the whole 32-bit pattern (V3-2)."""
    return _signed32(raw(a) & raw(b)) / STEPS


def bit_or(a: float, b: float) -> float:
    return _signed32(raw(a) | raw(b)) / STEPS


def toggle_byte(a: float) -> float:
    """``~`` toggles the bits of a byte (001:1978): ``~5`` is 250. What it does to anything else is not said."""
    if a != int(a) or not 0 <= a <= 255:
        raise NotSimulated("~", "of a value that is not a whole number from 0 to 255")
    return float(int(a) ^ 0xFF)


def negate(a: float) -> float:
    return _checked(-raw(a), "-")


BINARY_OPERATORS = spelled(
    {"+": add, "-": subtract, "*": multiply, "/": divide, "MOD": modulo, "AND": bit_and, "OR": bit_or}
)
"""The v3 operators (001:1966-1984); v3 has no XOR. ``NOT`` and the relational operators give 1 or 0 as in
v4 (V3-2)."""

UNARY_OPERATORS: Mapping[str, Callable[[float], float]] = MappingProxyType(
    {"-": negate, "+": fixed, "~": toggle_byte, "NOT": logical_not, "!": logical_not}
)
