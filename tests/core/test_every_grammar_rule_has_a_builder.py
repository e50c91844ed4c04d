"""Every kind of statement and expression the grammar can produce is built into its own syntax node.

``syntax/build.py`` dispatches on the tree's rule name, and takes a statement it has no builder for
as a one-word block statement (``ELSE``, ``NEXT``); a rule added to ``grammar.lark`` without a
builder would silently become one. These tests read the grammar itself, in both dialects.
"""

from __future__ import annotations

import lark
import pytest

from mintlang.dialect import Dialect
from mintlang.syntax import build
from mintlang.syntax.grammars import grammar_text

# the precedence levels of grammar.lark, loosest first, then the operands
_EXPRESSION_RULES = frozenset(
    [
        *("expr", "and_expr", "or_expr", "eq_expr", "rel_expr", "sum", "product"),
        *("unary", "bare_operand", "atom", "bare_atom"),
    ]
)


def _rules(dialect: Dialect) -> list[lark.grammar.Rule]:
    return lark.Lark(grammar_text(dialect), parser="lalr", maybe_placeholders=False).rules


@pytest.mark.parametrize("dialect", [Dialect.V4, Dialect.V3])
def test_each_statement_rule_has_a_builder_or_is_one_word(dialect: Dialect) -> None:
    rules = _rules(dialect)
    statements = {rule.expansion[0].name for rule in rules if rule.origin.name == "statement"}
    assert statements, "the grammar's ?statement alternatives"
    one_word = {
        name
        for name in statements
        if all(len(rule.expansion) == 1 and rule.expansion[0].is_term for rule in rules if rule.origin.name == name)
    }
    assert statements - one_word - set(build._STATEMENTS) == set()
    assert one_word >= {"else_", "endif", "next_", "repeat", "endw", "loop", "endl", "exit_", "return_", "end"}


@pytest.mark.parametrize("dialect", [Dialect.V4, Dialect.V3])
def test_each_expression_form_has_a_builder(dialect: Dialect) -> None:
    forms = {rule.alias for rule in _rules(dialect) if rule.origin.name in _EXPRESSION_RULES and rule.alias}
    assert forms == set(build._EXPRESSIONS)
