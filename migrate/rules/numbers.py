"""X-NUM: arithmetic that depended on v3's 1/256 fixed-point numbers.

v3 keeps three decimal places of a literal and rounds it to the nearest 256th:
``PRINT 1.002`` shows 1.003 (257/256), 0.15 is 38/256 and shows 0.148
(v3:1161-1181; the runtime's v3 numbers hold them so). v4 uses
floating point (v4:715-741). Flagged: a literal whose v3 value shows differently
at three decimals, an ``=``/``<>`` test on a fractional value (a literal or a
division), and a FOR with a fractional bound or STEP (the loop count can change).
Dyadic fractions (0.5, 0.25) are exact in both and are not flagged.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.migrate.context import FRACTION, Context, operator_tag
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.base import Action, Rule
from mintlang.runtime.dialects.v3.numbers import fixed
from mintlang.runtime.errors import NotSimulated
from mintlang.syntax import nodes as n

_PLACES = 3  # v3 keeps three decimal places before scaling (v3:1175-1179)


def v3_value(value: float) -> float | None:
    """The value Mint v3 holds for a literal, or None for one outside v3's range."""
    try:
        return fixed(round(value, _PLACES))
    except NotSimulated:
        return None


def shows_differently(value: float) -> bool:
    held = v3_value(value)
    return held is not None and round(held, _PLACES) != round(value, _PLACES)


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
    summary = "fractional literal that v3 stored inexactly, '=' on fractions, fractional FOR -> manual"
    evidence = "spec X-NUM; v3:1168-1181, v3:5684; v4:715-741"

    def apply(self, context: Context) -> Iterator[Action]:
        for file, line in context.placed(FRACTION, operator_tag("/")):  # what every pattern needs
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
    for node in nodes:
        if isinstance(node, n.Number) and shows_differently(node.value):
            return f"{node.text} was {v3_value(node.value):.3f} in v3 (1/256 fixed point), exact in v4"
    return None
