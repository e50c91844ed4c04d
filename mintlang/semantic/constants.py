"""Compile-time values of expressions made only of literals and predefined constants."""

from __future__ import annotations

import math
from collections.abc import Callable

from mintlang import binary32
from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.syntax import nodes as n


def constant_value(
    expression: n.Expression | None, dialect: Dialect = Dialect.V4, *, rounded: Callable[[float], float] | None = None
) -> float | None:
    """The value of ``expression`` when it is known before the program runs, else None.

    Worked out exactly (in double precision), as rules compare it with the manual's decimal limits,
    unless ``rounded`` is given: then each number and each result passes through it.
    """
    kind = type(expression)  # exact types, not class patterns: rules ask this for every axis and value
    if kind is n.Number:
        value = expression.value  # type: ignore[union-attr]
    elif kind is n.CharConstant:
        value = float(expression.value)  # type: ignore[union-attr]
    elif kind is n.ConstantRef:
        db = database()
        table = db.constants_of(dialect) if dialect.modern else db.v3_constants
        record = table.get(expression.name)  # type: ignore[union-attr]
        value = record.value if record is not None else None
    elif kind is n.Parenthesised:
        return constant_value(expression.expression, dialect, rounded=rounded)  # type: ignore[union-attr]
    elif kind is n.Unary:
        operand = constant_value(expression.operand, dialect, rounded=rounded)  # type: ignore[union-attr]
        if operand is None:
            return None
        return {"-": -operand, "+": operand, "NOT": float(operand == 0)}.get(expression.operator)  # type: ignore[union-attr]
    elif kind is n.Binary:
        left = constant_value(expression.left, dialect, rounded=rounded)  # type: ignore[union-attr]
        right = constant_value(expression.right, dialect, rounded=rounded)  # type: ignore[union-attr]
        if left is None or right is None:
            return None
        value = binary_value(expression.operator, left, right)  # type: ignore[union-attr]
    else:
        return None
    return value if rounded is None or value is None else rounded(value)


def held_value(expression: n.Expression | None, dialect: Dialect = Dialect.V4) -> float | None:
    """The value a Mint v4 or MintMT controller works out for ``expression``, when known before it runs.

    It holds every number in an 8-bit exponent and a 24-bit mantissa (000:714-716), a binary32
    float, so each literal and each result is rounded: ``0.1+0.2-0.3`` is 0 there, not 5.6e-17,
    and ``16777217`` is 16777216. None also when a result is too large to hold (the run's error 3).
    """
    try:
        return constant_value(expression, dialect, rounded=binary32.rounded)
    except OverflowError:
        return None


def binary_value(operator: str, a: float, b: float) -> float | None:
    """``a operator b`` in double precision; None where Mint gives no number (a zero divisor) or none is known."""
    match operator:
        case "+":
            return a + b
        case "-":
            return a - b
        case "*":
            return a * b
        case "/":
            return a / b if b else None
        case "MOD":
            return math.fmod(a, b) if b else None
        case "AND" | "OR" | "XOR":
            return _bitwise(operator, a, b)
    return None


_WORD = 1 << 24
"""Bitwise operators take their operands as 24-bit values (000:1338-1340)."""


def _bitwise(operator: str, a: float, b: float) -> float | None:
    """``a AND b``, ``a | b`` ... of whole numbers in one word; how a fraction or a sign is taken is not documented."""
    if not all(value == int(value) and 0 <= value < _WORD for value in (a, b)):
        return None
    x, y = int(a), int(b)
    return float({"AND": x & y, "OR": x | y, "XOR": x ^ y}[operator])


def constant_integer(expression: n.Expression | None, dialect: Dialect = Dialect.V4) -> int | None:
    """The value of a constant expression when it is a whole number, and one the controller can hold: a literal
    beyond a Mint number is error 3 already, and a rule naming the number it rounds to would misquote it."""
    value = constant_value(expression, dialect)
    if value is None or not binary32.holds(value) or value != int(value):
        return None
    return int(value)
