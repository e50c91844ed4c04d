"""lark's LALR parser over one logical line, with a cache by token kinds.

An LR parse depends only on the sequence of terminal kinds, never on token
texts, so the tree shape computed for ``KEYWORD EQUAL NUMBER`` serves every
``SPEED = 10`` and ``ACCEL = 2000`` of a program; the cache keeps it compiled
into a builder (``build.py``). Leaves of cached trees hold
the position of their token in the line (``Token.start_pos``), and subtrees
the positions of their first and last token (``Tree.meta``); the builder reads
texts and spans from the line itself.
"""

from __future__ import annotations

import hashlib
import io
import pickle
from collections.abc import Iterator
from functools import cache
from typing import BinaryIO

import lark
from lark import Lark, Token, Tree
from lark.common import LexerConf
from lark.exceptions import UnexpectedInput, UnexpectedToken
from lark.lexer import Lexer

from mintlang.dialect import Dialect
from mintlang.package_data import read_bytes, read_text
from mintlang.records import record
from mintlang.syntax.build import LineBuilder, compile_line
from mintlang.syntax.lexer import MAX_TOKENS
from mintlang.syntax.tokens import TokenKind


class _PresetTokens(Lexer):
    """Hands lark the tokens our own lexer made (lark's regex lexer cannot lex Mint)."""

    def __init__(self, lexer_conf: LexerConf) -> None:  # lark's Lexer interface
        del lexer_conf

    def lex(self, data: list[Token]) -> Iterator[Token]:  # type: ignore[override]
        return iter(data)


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


def build_parser(dialect: Dialect) -> Lark:
    """The parser made from the grammar: its LALR tables take a tenth of a second to compute."""
    # propagate_positions gives every subtree the positions of its first and last token, which
    # here are token indices: computed once per cached tree, they make node spans O(1).
    return Lark(grammar_text(dialect), parser="lalr", lexer=_PresetTokens, strict=True, propagate_positions=True)


def shipped_tables(dialect: Dialect) -> tuple[str, BinaryIO]:
    """The parser of ``dialect`` the package ships with its tables computed (``tools/lalr_tables.py``):
    the fingerprint of what it was made from, and lark's serialization of it."""
    made_from, _, tables = read_bytes("mintlang.syntax", f"lalr_{grammar_of(dialect).value}.bin").partition(b"\n")
    return made_from.decode("ascii"), io.BytesIO(tables)


def fingerprint(dialect: Dialect) -> str:
    """What shipped tables must have been computed from: this grammar, with this lark."""
    digest = hashlib.sha256(grammar_text(dialect).encode("utf-8")).hexdigest()
    return f"{digest} lark-{lark.__version__}"


@cache
def _parser(dialect: Dialect) -> Lark:
    """The shipped parser when it was made from this grammar by this lark (loading it takes a few ms,
    which every ``mint check`` pays at start-up), else one built now."""
    try:
        made_from, tables = shipped_tables(dialect)
        if made_from == fingerprint(dialect):
            return Lark.load(tables)
    except (OSError, ValueError, EOFError, pickle.UnpicklingError):
        pass  # missing or unreadable: build it
    return build_parser(dialect)


# Beyond these the line is not analysed: the controller takes 255 characters a line,
# and the tree builder and the rules recurse once per level of nesting. The lexer
# stops at MAX_TOKENS and makes the rest of the line one more token.
MAX_DEPTH = 200


@record
class ParseFailure:
    """Where the grammar stopped: the index of the offending token (len = end of line).

    ``too_complex`` is set instead when the line is too long or too deeply
    nested to analyse.
    """

    index: int
    expected: frozenset[str]
    too_complex: str | None = None


ParseResult = LineBuilder | ParseFailure

_results: dict[tuple[Dialect, tuple[TokenKind, ...]], ParseResult] = {}
_CACHE_LIMIT = 200_000


def clear_cache() -> None:
    _results.clear()


def parse_kinds(kinds: tuple[TokenKind, ...], dialect: Dialect = Dialect.V4) -> ParseResult:
    """The builder for lines with these token kinds, or where the grammar rejects them."""
    grammar = grammar_of(dialect)
    key = (grammar, kinds)
    result = _results.get(key)
    if result is None:
        result = _parse(kinds, grammar)
        if len(_results) >= _CACHE_LIMIT:
            _results.clear()
        _results[key] = result
    return result


def _parse(kinds: tuple[TokenKind, ...], dialect: Dialect) -> ParseResult:
    if len(kinds) > MAX_TOKENS:
        return ParseFailure(0, frozenset(), f"more than {MAX_TOKENS} tokens on one line")
    stream = [Token(kind.value, kind.value, start_pos=index, end_pos=index) for index, kind in enumerate(kinds)]
    try:
        tree = _parser(dialect).parse(stream)  # type: ignore[arg-type]
    except UnexpectedToken as error:
        index = error.token.start_pos if error.token.type != "$END" else len(kinds)
        return ParseFailure(index if index is not None else len(kinds), frozenset(error.expected))
    except UnexpectedInput:
        return ParseFailure(len(kinds), frozenset())
    depth = _depth(tree)
    if depth > MAX_DEPTH:
        return ParseFailure(0, frozenset(), f"expressions nested {depth} deep")
    for subtree in tree.iter_subtrees():
        subtree.data = str(subtree.data)  # lark names rules with Tokens, slow to hash
    return compile_line(tree)


def _depth(tree: Tree) -> int:
    """Height of a tree, measured without recursion."""
    deepest = 0
    stack = [(tree, 1)]
    while stack:
        node, depth = stack.pop()
        deepest = max(deepest, depth)
        stack.extend((child, depth + 1) for child in node.children if isinstance(child, Tree))
    return deepest
