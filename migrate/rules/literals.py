"""Constant values written in a statement, as the rules that rewrite by value need them."""

from __future__ import annotations

from mintlang.syntax import nodes as n


def integer_literal(value: n.Expression | None) -> int | None:
    """An integer literal, with its sign (``-1`` parses as a unary minus); None for anything else."""
    sign = 1
    if isinstance(value, n.Unary) and value.operator == "-":
        sign, value = -1, value.operand
    if isinstance(value, n.Number) and value.value == int(value.value):
        return sign * int(value.value)
    return None
