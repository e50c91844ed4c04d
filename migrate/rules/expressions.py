"""Expression rewrites that keep v3 values where v4 computes differently.

Each recognises its own output (``(SIN(x) * 1000)``, ``(~x & 255)``, a bracketed
AND inside an OR), so migrating migrated text changes nothing.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.diagnostics import Span
from mintlang.migrate.context import Context, operator_tag
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.base import Action, Rule
from mintlang.syntax import nodes as n
from mintlang.syntax.parents import ancestors, parent_of


def _wrapped(statement: n.Statement, node: n.Expression, operator: str, number: float) -> bool:
    """Whether ``node`` already sits in ``(node <operator> number)``."""
    enclosing = ancestors(statement, node)
    parent = next(enclosing, None)
    return (
        isinstance(parent, n.Binary)
        and parent.operator == operator
        and parent.left is node
        and isinstance(parent.right, n.Number)
        and parent.right.value == number
        and isinstance(next(enclosing, None), n.Parenthesised)
    )


def _bracketed(statement: n.Statement, node: n.Expression, text: str) -> str:
    """``(text)``, the rewrite of ``node``; the operand of a call written without brackets (``ABS SIN 200``)
    gets a second pair: the call takes the first as its own (``ABS (SIN(200) * 1000)`` is read as ``ABS(...)``),
    so ``_wrapped`` would not find the rewrite on the next pass and would multiply it again."""
    parent = parent_of(statement, node)
    if isinstance(parent, n.Call) and not parent.bracketed:
        return f"(({text}))"
    return f"({text})"


def _expressions(context: Context, *wanted: object) -> Iterator[tuple[object, n.Statement, n.Expression]]:
    """Every expression of the lines with one of the ``wanted`` tags, with its statement."""
    for file, _, statement in context.statements(*wanted):
        for root in n.expressions_of(statement):
            for node in n.walk_expression(root):
                yield file, statement, node


class Trigonometry(Rule):
    """v3 SIN, COS and TAN return the value times 1000 (COS(30) = 866, TAN(45) = 1000); v4
    returns the fraction. ``SIN(x)`` becomes ``(SIN(x) * 1000)``; the unbracketed ``SIN 90 + a``
    keeps its v3 binding as ``(SIN(90) * 1000) + a``. (v3 used a 0.1 degree table, so the last
    digit can differ.)"""

    id = "M-TRIG"
    rule_class = RuleClass.MECHANICAL
    phase = Phase.CONTEXT
    summary = "SIN(x), COS(x), TAN(x) -> (SIN(x) * 1000) ... (v3 returned thousandths)"
    evidence = "spec M-TRIG; v3:2063-2081, v3:7045, v3:11771, v3:11975; v4:8676-8679"

    def apply(self, context: Context) -> Iterator[Action]:
        for file, statement, node in _expressions(context, "SIN", "COS", "TAN"):
            if not isinstance(node, n.Call) or node.function not in ("SIN", "COS", "TAN"):
                continue
            if _wrapped(statement, node, "*", 1000):
                continue
            text = file.slice(node.span)  # type: ignore[attr-defined]
            if not node.bracketed:
                argument = node.arguments[0]
                text = f"{node.spelling}({file.slice(argument.span)})"  # type: ignore[attr-defined]
            yield self.replace(file, node.span, _bracketed(statement, node, f"{text} * 1000"))  # type: ignore[arg-type]


class ByteToggle(Rule):
    """v3 ``~`` toggles the 8 bits of a byte; v4 ``~`` works on 24 bits. ``~x`` becomes
    ``(~x & 255)``, which gives the v3 value for any byte."""

    id = "M-TILDE"
    rule_class = RuleClass.MECHANICAL
    phase = Phase.CONTEXT
    summary = "~x -> (~x & 255) (v3 toggled 8 bits, v4 toggles 24)"
    evidence = "spec M-TILDE; v3:1978; v4:5707-5708, v4:1340"

    def apply(self, context: Context) -> Iterator[Action]:
        for file, statement, node in _expressions(context, operator_tag("~")):
            if not isinstance(node, n.Unary) or node.operator != "~":
                continue
            if not _wrapped(statement, node, "AND", 255):
                text = f"{file.slice(node.span)} & 255"  # type: ignore[attr-defined]
                yield self.replace(file, node.span, _bracketed(statement, node, text))  # type: ignore[arg-type]


class Precedence(Rule):
    """v3 binds AND tighter than OR; the v4 table lists ``|`` above ``&``. In a chain mixing
    the two, every run of operands joined by AND gets brackets, which reads the same under
    either rule. The shared parser builds one tree for both dialects (v4 precedence), so the
    chain is flattened to its operands in source order and regrouped the v3 way here."""

    id = "M-PREC"
    rule_class = RuleClass.MECHANICAL
    phase = Phase.CONTEXT
    summary = "a AND b OR c -> (a AND b) OR c, bracketed as v3 binds it"
    evidence = "spec M-PREC; v3:1986-1995; v4:1417-1429"

    def apply(self, context: Context) -> Iterator[Action]:
        for file, statement, node in _expressions(context, operator_tag("AND")):  # a chain needs both
            if not _logical(node):
                continue
            if _logical(parent_of(statement, node)):
                continue  # not the top of its chain
            operands, operators = _flatten(node)
            if not {"AND", "OR"} <= set(operators):
                continue
            for first, last in _and_runs(operators):
                span = (operands[first].span.start, operands[last].span.end)
                text = file.text[span[0] : span[1]]  # type: ignore[attr-defined]
                yield self.replace(file, Span(*span), f"({text})")  # type: ignore[arg-type]


def _logical(node: n.Expression | None) -> bool:
    return isinstance(node, n.Binary) and node.operator in ("AND", "OR")


def _flatten(node: n.Expression) -> tuple[list[n.Expression], list[str]]:
    """The operands and AND/OR operators of a chain, in source order."""
    if not _logical(node):
        return [node], []
    assert isinstance(node, n.Binary)
    left, left_ops = _flatten(node.left)
    right, right_ops = _flatten(node.right)
    return [*left, *right], [*left_ops, node.operator, *right_ops]


def _and_runs(operators: list[str]) -> Iterator[tuple[int, int]]:
    """Operand index ranges joined only by AND (two operands or more)."""
    start = 0
    for index, operator in enumerate([*operators, "OR"]):
        if operator == "OR":
            if index > start:
                yield start, index
            start = index + 1
