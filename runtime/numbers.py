"""Mint's numeric model: every value is an IEEE binary32 float (spec NM-1, RC).

The manual describes an 8-bit exponent with a 24-bit mantissa; binary32 with
round-to-nearest-even reproduces every printed example, so each result here is
computed in double precision and rounded once with ``f32``. For ``+ - * /`` on
binary32 operands that single rounding equals true binary32 arithmetic.

A result too large for binary32 raises error 3 ("out of range") instead of
becoming an infinity, so no infinity or NaN ever reaches a Mint variable.
"""

from __future__ import annotations

import math
import struct
from collections.abc import Callable, Mapping
from types import MappingProxyType

from mintlang import binary32
from mintlang.runtime.errors import OUT_OF_RANGE, MintError

DIVIDE_BY_ZERO = 2021
MASK24 = 0xFFFFFF

_BINARY32 = struct.Struct("<f")
_pack = _BINARY32.pack
_unpack = _BINARY32.unpack


def f32(x: float) -> float:
    """Round ``x`` to the nearest binary32 value; this runs after every operation, so it stays minimal."""
    try:
        return _unpack(_pack(x))[0]
    except OverflowError:
        raise MintError(OUT_OF_RANGE, detail="number too large") from None


def held(value: float, number: Callable[[float], float]) -> float:
    """A literal's ``value`` as the dialect's ``number`` holds it; one too large even for a double (1 and
    400 zeros) is out of range as one too large for binary32 is (``f32`` cannot tell: it keeps an infinity)."""
    if math.isinf(value):
        raise MintError(OUT_OF_RANGE, detail="number too large")
    return number(value)


def bits24(x: float) -> int:
    """The 24-bit pattern bitwise operators see: truncated toward zero, reduced modulo 2**24 (NM-3 RC)."""
    return int(x) & MASK24


def add(a: float, b: float) -> float:
    return f32(a + b)


def subtract(a: float, b: float) -> float:
    return f32(a - b)


def multiply(a: float, b: float) -> float:
    return f32(a * b)


def divide(a: float, b: float) -> float:
    """Division; the controller stops with error 2021 where Python would raise or return infinity."""
    if b == 0:
        raise MintError(DIVIDE_BY_ZERO)
    return f32(a / b)


def modulo(a: float, b: float) -> float:
    """``MOD``/``%`` with C ``fmod`` semantics: the sign follows the dividend, fractions allowed (NM-3 RC)."""
    if b == 0:
        raise MintError(DIVIDE_BY_ZERO)
    return f32(math.fmod(a, b))


def bit_and(a: float, b: float) -> float:
    return float(bits24(a) & bits24(b))


def bit_or(a: float, b: float) -> float:
    return float(bits24(a) | bits24(b))


def bit_xor(a: float, b: float) -> float:
    return float(bits24(a) ^ bits24(b))


def bit_not(a: float) -> float:
    """``~``: the unsigned 24-bit complement, so ``~2`` is 16777213 and prints in HEX as FFFFFD."""
    return float(bits24(a) ^ MASK24)


def logical_not(a: float) -> float:
    """``NOT``/``!``: 1 for zero, otherwise 0 (NM-3)."""
    return 1.0 if a == 0 else 0.0


def negate(a: float) -> float:
    return -a


def equal(a: float, b: float) -> float:
    return 1.0 if a == b else 0.0


def not_equal(a: float, b: float) -> float:
    return 1.0 if a != b else 0.0


def less(a: float, b: float) -> float:
    return 1.0 if a < b else 0.0


def greater(a: float, b: float) -> float:
    return 1.0 if a > b else 0.0


def less_equal(a: float, b: float) -> float:
    return 1.0 if a <= b else 0.0


def greater_equal(a: float, b: float) -> float:
    return 1.0 if a >= b else 0.0


_SYMBOLS = {"MOD": "%", "AND": "&", "OR": "|"}  # a word operator's symbol form


def spelled(arithmetic: Mapping[str, Callable[[float, float], float]]) -> Mapping[str, Callable[[float, float], float]]:
    """A dialect's binary operators by spelling (upper case): its ``arithmetic`` (``+ - * /`` and the words
    ``MOD``, ``AND``, ``OR``, ``XOR``), each word under its symbol too, and the comparisons, 1 or 0 in every
    dialect. One table of spellings, so that v3 and v4 cannot spell an operator differently."""
    symbols = {_SYMBOLS[word]: operate for word, operate in arithmetic.items() if word in _SYMBOLS}
    comparisons = {"=": equal, "<>": not_equal, "<": less, ">": greater, "<=": less_equal, ">=": greater_equal}
    return MappingProxyType({**arithmetic, **symbols, **comparisons})


BINARY_OPERATORS = spelled(
    {"+": add, "-": subtract, "*": multiply, "/": divide, "MOD": modulo, "AND": bit_and, "OR": bit_or, "XOR": bit_xor}
)
"""Binary operators by spelling (upper case); both the word and the symbol form are keys."""

UNARY_OPERATORS: Mapping[str, Callable[[float], float]] = MappingProxyType(
    {"-": negate, "+": f32, "~": bit_not, "NOT": logical_not, "!": logical_not}
)
"""Prefix operators by spelling; unary ``+`` only normalises its operand to binary32."""


def _abs(x: float) -> float:
    return abs(x)


def _int(x: float) -> float:
    """``INT`` truncates toward zero (``INT(-2.5)`` is -2), unlike BASIC's floor."""
    return float(math.trunc(x))


def _sqrt(x: float) -> float:
    """The controller answers 0 for a negative argument instead of failing (NM-5)."""
    return f32(math.sqrt(x)) if x > 0 else 0.0


def _log(x: float) -> float:
    """Natural log; the manual only defines it above 0, so 0 and below raise error 3."""
    if x <= 0:
        raise MintError(OUT_OF_RANGE, detail="LOG of a number that is not positive")
    return f32(math.log(x))


def _exp(x: float) -> float:
    try:
        return binary32.exp(x)
    except OverflowError:
        raise MintError(OUT_OF_RANGE, detail="EXP too large") from None


def _pow(x: float, y: float) -> float:
    """``POW(x, y)`` without NextMove's exponent restriction (NM-5 RC); 0 to a negative power is a divide by zero."""
    try:
        return binary32.power(x, y)
    except ZeroDivisionError:
        raise MintError(DIVIDE_BY_ZERO, detail="POW of 0 to a negative power") from None
    except ValueError:
        raise MintError(OUT_OF_RANGE, detail="POW has no real result") from None
    except OverflowError:
        raise MintError(OUT_OF_RANGE, detail="POW too large") from None


def _sin(degrees: float) -> float:
    return f32(math.sin(math.radians(degrees)))


def _cos(degrees: float) -> float:
    return f32(math.cos(math.radians(degrees)))


def _tan(degrees: float) -> float:
    """Tangent in degrees; ``TAN 90`` is huge rather than an error, because pi/2 radians is never exact."""
    return f32(math.tan(math.radians(degrees)))


def _inverse(function: Callable[[float], float], name: str) -> Callable[[float], float]:
    """``ASIN``/``ACOS`` in degrees; outside -1..1 there is no angle, which is error 3."""

    def inverse(x: float) -> float:
        if not -1 <= x <= 1:
            raise MintError(OUT_OF_RANGE, detail=f"{name} of a number outside -1 to 1")
        return f32(math.degrees(function(x)))

    return inverse


def _atan(x: float) -> float:
    return f32(math.degrees(math.atan(x)))


def _chr(x: float) -> float:
    """``CHR(n)`` is the code itself; only ``PRINT`` turns it into a character (``printing.format_chr``)."""
    return x


FUNCTIONS: Mapping[str, Callable[..., float]] = MappingProxyType(
    {
        "ABS": _abs,
        "ACOS": _inverse(math.acos, "ACOS"),
        "ASIN": _inverse(math.asin, "ASIN"),
        "ATAN": _atan,
        "CHR": _chr,
        "COS": _cos,
        "EXP": _exp,
        "INT": _int,
        "LOG": _log,
        "POW": _pow,
        "SIN": _sin,
        "SQRT": _sqrt,
        "TAN": _tan,
    }
)
"""Mint's numeric functions by name; arguments are binary32 values, results are binary32 values."""
