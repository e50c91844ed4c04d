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

from collections.abc import Iterator
from dataclasses import dataclass
from functools import cache
from importlib import resources

from lark import Lark, Token, Tree
from lark.common import LexerConf
from lark.exceptions import UnexpectedInput, UnexpectedToken
from lark.lexer import Lexer

from mintlang.syntax.build import LineBuilder, compile_line
from mintlang.syntax.tokens import TokenKind


class _PresetTokens(Lexer):
    """Hands lark the tokens our own lexer made (lark's regex lexer cannot lex Mint)."""

    def __init__(self, lexer_conf: LexerConf) -> None:  # lark's Lexer interface
        del lexer_conf

    def lex(self, data: list[Token]) -> Iterator[Token]:  # type: ignore[override]
        return iter(data)


@cache
def _parser() -> Lark:
    grammar = resources.files("mintlang.syntax").joinpath("grammar.lark").read_text(encoding="utf-8")
    # propagate_positions gives every subtree the positions of its first and last token, which
    # here are token indices: computed once per cached tree, they make node spans O(1).
    return Lark(grammar, parser="lalr", lexer=_PresetTokens, strict=True, propagate_positions=True)


# Beyond these the line is not analysed: the controller takes 255 characters a line,
# and the tree builder and the rules recurse once per level of nesting.
MAX_TOKENS = 20_000
MAX_DEPTH = 200


@dataclass(frozen=True, slots=True)
class ParseFailure:
    """Where the grammar stopped: the index of the offending token (len = end of line).

    ``too_complex`` is set instead when the line is too long or too deeply
    nested to analyse.
    """

    index: int
    expected: frozenset[str]
    too_complex: str | None = None


ParseResult = LineBuilder | ParseFailure

_results: dict[tuple[TokenKind, ...], ParseResult] = {}
_CACHE_LIMIT = 200_000


def clear_cache() -> None:
    _results.clear()


def parse_kinds(kinds: tuple[TokenKind, ...]) -> ParseResult:
    """The builder for lines with these token kinds, or where the grammar rejects them."""
    result = _results.get(kinds)
    if result is None:
        result = _parse(kinds)
        if len(_results) >= _CACHE_LIMIT:
            _results.clear()
        _results[kinds] = result
    return result


def _parse(kinds: tuple[TokenKind, ...]) -> ParseResult:
    if len(kinds) > MAX_TOKENS:
        return ParseFailure(0, frozenset(), f"{len(kinds)} tokens on one line")
    stream = [Token(kind.value, kind.value, start_pos=index, end_pos=index) for index, kind in enumerate(kinds)]
    try:
        tree = _parser().parse(stream)  # type: ignore[arg-type]
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
