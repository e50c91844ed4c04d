"""X-NUM: arithmetic that depended on v3's 1/256 fixed-point numbers.

v3 keeps three decimal places of a literal and stores the fraction in 1/256
steps, truncating: 0.15 is 38/256 and prints as 0.148 (v3:1168-1181). v4 uses
floating point (v4:715-741). Flagged: a literal whose v3 value shows differently
at three decimals, an ``=``/``<>`` test on a fractional value (a literal or a
division), and a FOR with a fractional bound or STEP (the loop count can change).
Dyadic fractions (0.5, 0.25) are exact in both and are not flagged.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

from mintlang.migrate.context import FRACTION, Context, operator_tag
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.base import Action, Rule
from mintlang.syntax import nodes as n

_STEPS = 256  # v3 fraction resolution (v3:1171)
_PLACES = 1000  # v3 keeps three decimal places before scaling (v3:1175-1179)


def v3_value(value: float) -> float:
    """The value Mint v3 stores for a non-negative literal: truncated to 1/256 steps."""
    whole = math.floor(value)
    thousandths = round((value - whole) * _PLACES)
    return whole + (thousandths * _STEPS // _PLACES) / _STEPS


def shows_differently(value: float) -> bool:
    return round(v3_value(value), 3) != round(value, 3)


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
