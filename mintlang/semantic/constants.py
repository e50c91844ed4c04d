"""Compile-time values of expressions made only of literals and predefined constants."""

from __future__ import annotations

import math

from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.syntax import nodes as n


def constant_value(expression: n.Expression | None, dialect: Dialect = Dialect.V4) -> float | None:
    """The value of ``expression`` when it is known before the program runs, else None."""
    kind = type(expression)  # exact types, not class patterns: rules ask this for every axis and value
    if kind is n.Number:
        return expression.value  # type: ignore[union-attr]
    if kind is n.CharConstant:
        return float(expression.value)  # type: ignore[union-attr]
    if kind is n.ConstantRef:
        db = database()
        table = db.constants_of(dialect) if dialect.modern else db.v3_constants
        record = table.get(expression.name)  # type: ignore[union-attr]
        return record.value if record is not None else None
    if kind is n.Parenthesised:
        return constant_value(expression.expression, dialect)  # type: ignore[union-attr]
    if kind is n.Unary:
        value = constant_value(expression.operand, dialect)  # type: ignore[union-attr]
        if value is None:
            return None
        return {"-": -value, "+": value, "NOT": float(value == 0)}.get(expression.operator)  # type: ignore[union-attr]
    if kind is n.Binary:
        left = constant_value(expression.left, dialect)  # type: ignore[union-attr]
        right = constant_value(expression.right, dialect)  # type: ignore[union-attr]
        if left is None or right is None:
            return None
        return _binary(expression.operator, left, right)  # type: ignore[union-attr]
    return None


def _binary(operator: str, a: float, b: float) -> float | None:
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
    """The value of a constant expression when it is a whole number."""
    value = constant_value(expression, dialect)
    if value is None or value != int(value):
        return None
    return int(value)
