"""``mintlang.syntax.parents``: what encloses an expression, at its own place, without a map."""

from __future__ import annotations

import mintlang
from mintlang.syntax import nodes as n
from mintlang.syntax.parents import ancestors, children, parent_of


def _assignment(line: n.Line) -> n.Assignment:
    statement = line.statements[0]
    assert isinstance(statement, n.Assignment)
    return statement


def test_each_of_two_equal_lines_finds_its_own_enclosing_expressions() -> None:
    lines = mintlang.parse("x = (a + 1) * 2\nx = (a + 1) * 2\n").lines
    for line in lines:
        statement = _assignment(line)
        product = statement.value
        assert isinstance(product, n.Binary) and isinstance(product.left, n.Parenthesised)
        total = product.left.expression
        assert isinstance(total, n.Binary)
        assert parent_of(statement, total.right) is total
        found = list(ancestors(statement, total.right))
        assert len(found) == 3 and all(a is b for a, b in zip(found, (total, product.left, product), strict=True))


def test_a_whole_expression_and_a_node_of_another_statement_have_no_parent() -> None:
    first, second = (_assignment(line) for line in mintlang.parse("x = -a\nx = -a\n").lines)
    assert parent_of(first, first.value) is None
    assert isinstance(second.value, n.Unary)
    assert parent_of(first, second.value.operand) is None  # equal, but not at this place


def test_children_in_source_order() -> None:
    statement = _assignment(mintlang.parse("x = POW(a, b) + SPEED[c, d]\n").lines[0])
    call, keyword = children(statement.value)
    assert [child.name.text for child in (*children(call), *children(keyword))] == ["a", "b", "c", "d"]  # type: ignore[union-attr]
