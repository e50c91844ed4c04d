"""Shared walks over the semantic model, so each rule states only its check."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from enum import StrEnum

from mintlang.semantic.model import SemanticModel
from mintlang.semantic.symbols import Unit
from mintlang.syntax import nodes as n


def statements(model: SemanticModel) -> Iterator[tuple[Unit, n.Line, n.Statement]]:
    """Every statement of both files in compile order, IF .. THEN bodies included."""
    for unit, document in model.documents():
        for line in document.lines:
            for statement in n.walk_statements(line.statements):
                yield unit, line, statement


class Use(StrEnum):
    """How a keyword is used where it is written."""

    READ = "read"  # inside an expression
    WRITE = "write"  # KW = value
    COMMAND = "command"  # KW or KW args as a statement


@dataclass(frozen=True, slots=True)
class KeywordUse:
    unit: Unit
    statement: n.Statement
    keyword: n.KeywordRef
    use: Use


def nodes_of(statement: n.Statement) -> Iterator[n.Expression]:
    """Every expression node a statement evaluates (not descending into IF .. THEN bodies)."""
    for expression in n.expressions_of(statement):
        yield from n.walk_expression(expression)


def keyword_uses(model: SemanticModel) -> Iterator[KeywordUse]:
    """Every keyword written in either file, with how it is used there."""
    for unit, _, statement in statements(model):
        if isinstance(statement, n.KeywordStatement):
            use = Use.WRITE if statement.values is not None else Use.COMMAND
            yield KeywordUse(unit, statement, statement.keyword, use)
        for node in nodes_of(statement):
            if isinstance(node, n.KeywordRef):
                yield KeywordUse(unit, statement, node, Use.READ)
