"""lark's LALR parser over one logical line, with a cache by token kinds.

An LR parse depends only on the sequence of terminal kinds, never on token
texts, so the tree shape computed for ``KEYWORD EQUAL NUMBER`` serves every
``SPEED = 10`` and ``ACCEL = 2000`` of a program. Leaves of cached trees hold
the position of their token in the line (``Token.start_pos``); the builder
reads texts and spans from the line itself.
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
    return Lark(grammar, parser="lalr", lexer=_PresetTokens, strict=True, propagate_positions=False)


@dataclass(frozen=True, slots=True)
class ParseFailure:
    """Where the grammar stopped: the index of the offending token (len = end of line)."""

    index: int
    expected: frozenset[str]


ParseResult = Tree | ParseFailure

_results: dict[tuple[TokenKind, ...], ParseResult] = {}
_CACHE_LIMIT = 200_000


def parse_kinds(kinds: tuple[TokenKind, ...]) -> ParseResult:
    """Parse a line given as its terminal kinds; the tree's leaves carry token positions."""
    result = _results.get(kinds)
    if result is None:
        result = _parse(kinds)
        if len(_results) >= _CACHE_LIMIT:
            _results.clear()
        _results[kinds] = result
    return result


def _parse(kinds: tuple[TokenKind, ...]) -> ParseResult:
    stream = [Token(kind.value, kind.value, start_pos=index) for index, kind in enumerate(kinds)]
    try:
        return _parser().parse(stream)  # type: ignore[arg-type]
    except UnexpectedToken as error:
        index = error.token.start_pos if error.token.type != "$END" else len(kinds)
        return ParseFailure(index if index is not None else len(kinds), frozenset(error.expected))
    except UnexpectedInput:
        return ParseFailure(len(kinds), frozenset())
