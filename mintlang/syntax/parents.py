"""The expressions that enclose an expression, found by walking the statement that holds it.

Syntax nodes keep no link to their parent, and no map can stand in for one: the
parser gives every line of the same text one shared syntax object, and frozen
nodes compare and hash by value, so a map keyed by a node, or by its ``id()``,
merges equal places (the runtime's block links once broke exactly so). A
statement holds a few dozen expressions, so walking it again for each question
is cheap, and the walk compares nodes with ``is``. That names one place only in
a tree with a node of its own at every place: ask it of the statements of
``Document.lines`` (``PlacedLine.absolute`` copies every node), never of a
``LineSyntax`` shared by several lines.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.syntax import nodes as n


def children(node: n.Expression) -> tuple[n.Expression, ...]:
    """The direct subexpressions of ``node``, in source order."""
    match node:
        case n.Binary(left=left, right=right):
            return (left, right)
        case n.Unary(operand=operand):
            return (operand,)
        case n.Parenthesised(expression=inner):
            return (inner,)
        case n.ElementRef(index=index):
            return (index,)
        case n.Call(arguments=arguments):
            return arguments
        case n.KeywordRef(selector=selector) if selector is not None:
            return tuple(item for item in selector.items if item is not None)
    return ()


def ancestors(statement: n.Statement, node: n.Expression) -> Iterator[n.Expression]:
    """The expressions of ``statement`` that enclose ``node``, innermost first: none for a
    whole expression of the statement, or for a node that is not in it."""
    return reversed(_path(statement, node))


def parent_of(statement: n.Statement, node: n.Expression) -> n.Expression | None:
    """The expression of ``statement`` that ``node`` is a direct subexpression of, or None."""
    return next(ancestors(statement, node), None)


def _path(statement: n.Statement, node: n.Expression) -> list[n.Expression]:
    """The expressions from a whole expression of ``statement`` down to ``node``, ``node`` left out:
    depth first, the path cut back to each node's depth as the walk reaches it."""
    for root in n.expressions_of(statement):
        if root is None or isinstance(root, n.StringLiteral):
            continue
        path: list[n.Expression] = []
        stack = [(root, 0)]
        while stack:
            current, depth = stack.pop()
            del path[depth:]
            if current is node:
                return path
            path.append(current)
            stack.extend((child, depth + 1) for child in reversed(children(current)))
    return []
