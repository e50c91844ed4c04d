"""One walk over the semantic model, shared by every rule.

The rules ask the same questions (every statement, every keyword and how it
is used, every array element); gathering the answers once keeps a check fast
enough to run on every keystroke in the language server.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum

from mintlang.semantic.model import SemanticModel
from mintlang.semantic.symbols import Unit
from mintlang.syntax import nodes as n


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


@dataclass(frozen=True, slots=True)
class Facts:
    """The model and what one walk over it found, in compile order."""

    model: SemanticModel
    statements: tuple[tuple[Unit, n.Line, n.Statement], ...]  # IF .. THEN bodies included
    keyword_uses: tuple[KeywordUse, ...]
    elements: tuple[tuple[Unit, n.ElementRef], ...]  # array elements read or written
    names: tuple[tuple[Unit, n.Name], ...]  # user words: variables read or written, bare words


def gather(model: SemanticModel) -> Facts:
    statements: list[tuple[Unit, n.Line, n.Statement]] = []
    uses: list[KeywordUse] = []
    elements: list[tuple[Unit, n.ElementRef]] = []
    names: list[tuple[Unit, n.Name]] = []
    for unit, document in model.documents():
        for line in document.lines:
            for statement in n.walk_statements(line.statements):
                statements.append((unit, line, statement))
                match statement:
                    case n.KeywordStatement(keyword=keyword, values=values):
                        uses.append(
                            KeywordUse(unit, statement, keyword, Use.WRITE if values is not None else Use.COMMAND)
                        )
                    case n.Assignment(target=target) | n.Input(target=target):
                        names.append((unit, target.name))
                        if isinstance(target, n.ElementRef):
                            elements.append((unit, target))
                    case n.BareName(name=name):
                        names.append((unit, name))
                for expression in n.expressions_of(statement):
                    for node in n.walk_expression(expression):
                        if isinstance(node, n.KeywordRef):
                            uses.append(KeywordUse(unit, statement, node, Use.READ))
                        elif isinstance(node, n.ElementRef):
                            elements.append((unit, node))
                            names.append((unit, node.name))
                        elif isinstance(node, n.VariableRef):
                            names.append((unit, node.name))
    return Facts(model, tuple(statements), tuple(uses), tuple(elements), tuple(names))
