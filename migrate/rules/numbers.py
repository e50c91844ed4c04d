"""X-NUM: arithmetic that depended on v3's 1/256 fixed-point numbers.

v3 keeps three decimal places of a literal and rounds it to the nearest 256th:
``PRINT 1.002`` shows 1.003 (257/256), 0.15 is 38/256 and shows 0.148
(v3:1161-1181; the runtime's v3 numbers hold them so). v4 uses
floating point (v4:715-741). Flagged: a literal whose v3 value shows differently
at three decimals, an ``=``/``<>`` test on a fractional value (a literal or a
division), a FOR with a fractional bound or STEP (the loop count can change), and
INT of a value that can be negative: v3 INT rounds down, so INT(x + .5) is the
nearest integer for either sign (v3:9270-9278), v4 INT rounds toward zero
(v4:12565-12568; spec §10 asks for a flag where negative values are possible).
Dyadic fractions (0.5, 0.25) are exact in both and are not flagged.
"""

from __future__ import annotations

from collections.abc import Iterator
from decimal import Decimal

from mintlang.keyworddb import database
from mintlang.migrate.context import FRACTION, Context, operator_tag
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.base import Action, Rule
from mintlang.runtime.dialects.v3.numbers import fixed
from mintlang.runtime.dialects.v3.printing import format_number
from mintlang.runtime.errors import NotSimulated
from mintlang.syntax import nodes as n

_PLACES = 3  # v3 keeps three decimal places before scaling (v3:1175-1179)


def v3_value(value: float) -> float | None:
    """The value Mint v3 holds for a literal, or None for one outside v3's range."""
    try:
        return fixed(round(value, _PLACES))
    except NotSimulated:
        return None


def _fractional(expression: n.Expression | None) -> bool:
    return any(
        (isinstance(node, n.Number) and node.value != int(node.value))
        or (isinstance(node, n.Binary) and node.operator == "/")
        for node in n.walk_expression(expression)
    )


class FixedPoint(Rule):
    """One manual item per statement, for the first of the three patterns it shows."""

    id = "X-NUM"
    rule_class = RuleClass.MANUAL
    phase = Phase.MANUAL
    summary = "fractional literal that v3 stored inexactly, '=' on fractions, fractional FOR, INT of a sign -> manual"
    evidence = "spec X-NUM, §10 INT; v3:1168-1181, v3:5684, v3:9270-9278; v4:715-741, v4:12565-12568"

    def apply(self, context: Context) -> Iterator[Action]:
        for file, line in context.placed(FRACTION, operator_tag("/"), "INT"):  # what every pattern needs
            for statement in n.flatten_statements(line.syntax.statements):
                reason = _reason(statement)
                if reason is not None:
                    yield self.flag(file, line.span(statement.span), reason)


def _reason(statement: n.Statement) -> str | None:
    if isinstance(statement, n.For) and any(
        _fractional(part) for part in (statement.start, statement.end, statement.step)
    ):
        return "fractional FOR: v3 counted in 1/256 steps, the number of passes can differ in v4"
    nodes = [node for root in n.expressions_of(statement) for node in n.walk_expression(root)]
    for node in nodes:
        if (
            isinstance(node, n.Binary)
            and node.operator in {"=", "<>"}
            and (_fractional(node.left) or _fractional(node.right))
        ):
            return "'=' on a fractional value: v3 compared 1/256 fixed-point values, v4 floating point"
    if _rounds_a_sign(statement, nodes):
        return "INT of a value that can be negative: v3 rounded it down (INT(-2.5) = -3), v4 toward zero (-2)"
    for node in nodes:
        if isinstance(node, n.Number) and (reason := _inexact(node)) is not None:
            return reason
    return None


def _rounds_a_sign(statement: n.Statement, nodes: list[n.Expression]) -> bool:
    """Whether the statement takes INT of a value that can be negative. SCALE takes positive values
    only (v3:11592, v4:15783), so M-SCALE's ``SCALE = INT(e)`` never rounds a negative."""
    if isinstance(statement, n.KeywordStatement) and statement.keyword.keyword == "SCALE":
        return False
    return any(
        isinstance(node, n.Call) and node.function == "INT" and not _unsigned(node.arguments[0]) for node in nodes
    )


def _unsigned(expression: n.Expression) -> bool:
    """Whether ``expression`` cannot be negative."""
    lowest = _lowest(expression)
    return lowest is not None and lowest >= 0


def _lowest(expression: n.Expression) -> float | None:
    """The least value ``expression`` can take, where its parts tell: a number (-2.5 is a unary minus),
    ABS, a keyword read by the bottom of its range (S-ANALOG's ``ADC.0 + 100``, ADC from -100,
    v4:6358), a sum of such, and a product or quotient of values that cannot be negative."""
    match expression:
        case n.Number(value=value):
            return value
        case n.Call(function="ABS"):
            return 0.0
        case n.Parenthesised(expression=inner):
            return _lowest(inner)
        case n.KeywordRef(keyword=keyword):
            return _range_bottom(keyword)
        case n.Binary(operator="+", left=left, right=right):
            parts = (_lowest(left), _lowest(right))
            return None if None in parts else sum(part for part in parts if part is not None)
        case n.Binary(operator="*" | "/", left=left, right=right):
            return 0.0 if _unsigned(left) and _unsigned(right) else None
    return None


def _range_bottom(keyword: str) -> float | None:
    """The lowest value of the keyword's range on any controller, None where one is not known."""
    entry = database().lookup(keyword)
    bottoms = [part.range.minimum if part.range else None for part in entry.attributes] if entry else [None]
    return None if not bottoms or None in bottoms else min(bottom for bottom in bottoms if bottom is not None)


def _inexact(literal: n.Number) -> str | None:
    """What v3 made of a literal whose value shows differently at three decimals: the 256ths it held
    and what PRINT showed, cut to three places (v3:1161-1181); None for one v3 held as written."""
    held = v3_value(literal.value)
    if held is None:
        return None
    shown = format_number(held)  # cut, not rounded: 0.004 is held as 1/256 and shows 0.003
    written = round(literal.value, _PLACES)
    if round(held, _PLACES) == written and Decimal(shown) == Decimal(str(written)):
        return None
    v3 = f"{round(held * 256)}/256 in v3 (1/256 fixed point; PRINT shows {shown})"
    return f"{literal.text} was {v3}, floating point in v4"
