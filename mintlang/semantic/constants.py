"""Compile-time values of expressions made only of literals and predefined constants."""

from __future__ import annotations

import math

from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.syntax import nodes as n


def constant_value(expression: n.Expression | None, dialect: Dialect = Dialect.V4) -> float | None:
    """The value of ``expression`` when it is known before the program runs, else None."""
    match expression:
        case n.Number(value=value):
            return value
        case n.CharConstant(value=value):
            return float(value)
        case n.ConstantRef(name=name):
            db = database()
            table = db.constants if dialect is Dialect.V4 else db.v3_constants
            record = table.get(name)
            return record.value if record is not None else None
        case n.Parenthesised(expression=inner):
            return constant_value(inner, dialect)
        case n.Unary(operator=operator, operand=operand):
            value = constant_value(operand, dialect)
            if value is None:
                return None
            return {"-": -value, "+": value, "NOT": float(value == 0)}.get(operator)
        case n.Binary(operator=operator, left=left, right=right):
            a, b = constant_value(left, dialect), constant_value(right, dialect)
            if a is None or b is None:
                return None
            return _binary(operator, a, b)
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
    return None


def constant_integer(expression: n.Expression | None, dialect: Dialect = Dialect.V4) -> int | None:
    """The value of a constant expression when it is a whole number."""
    value = constant_value(expression, dialect)
    if value is None or value != int(value):
        return None
    return int(value)
