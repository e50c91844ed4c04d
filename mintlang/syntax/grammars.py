"""The grammar of each dialect, as text: ``grammar.lark`` is v4's, and v3's differs in one place."""

from __future__ import annotations

from mintlang.dialect import Dialect
from mintlang.package_data import read_text

# Mint v3 binds AND tighter than OR (v3 guide 4.2, lines 1986-1995), v4 the other way round
# (3.4.7): the v3 grammar is the v4 one with the two levels swapped.
_V4_LOGIC = """?expr: and_expr
?and_expr: and_expr AND or_expr -> binary
    | or_expr
?or_expr: or_expr (OR | XOR) eq_expr -> binary
    | eq_expr
"""
_V3_LOGIC = """?expr: or_expr
?or_expr: or_expr (OR | XOR) and_expr -> binary
    | and_expr
?and_expr: and_expr AND eq_expr -> binary
    | eq_expr
"""


def grammar_of(dialect: Dialect) -> Dialect:
    """The dialect whose grammar reads ``dialect``: MintMT's differences are made by its lexer, so v4's."""
    return Dialect.V3 if dialect is Dialect.V3 else Dialect.V4


def grammar_text(dialect: Dialect) -> str:
    grammar = read_text("mintlang.syntax", "grammar.lark")
    assert _V4_LOGIC in grammar, "grammar.lark must state the v4 precedence of AND and OR as _V4_LOGIC"
    return grammar.replace(_V4_LOGIC, _V3_LOGIC) if grammar_of(dialect) is Dialect.V3 else grammar
