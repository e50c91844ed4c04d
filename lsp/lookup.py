"""Finding tokens of the core's lossless token stream at an offset, or of the line being typed."""

from __future__ import annotations

from bisect import bisect_right
from collections.abc import Collection, Sequence
from operator import attrgetter

from lsprotocol import types

from mintlang.dialect import Dialect
from mintlang.lsp.positions import Positions
from mintlang.syntax.lexer import lex
from mintlang.syntax.parser import Document
from mintlang.syntax.tokens import GRAMMAR_KEYWORDS, TRIVIA, WORDS, Token, TokenKind
from mintlang.syntax.vocabulary import Vocabulary

_START = attrgetter("start")
WORD_KINDS = WORDS | {TokenKind.LABEL}
_KEYWORD_KINDS = GRAMMAR_KEYWORDS | {TokenKind.KEYWORD, TokenKind.FUNCTION}
_SYMBOL_STATEMENTS = {"?": "PRINT"}  # a statement written as a symbol; operators (&, |, !) read as they are


def token_index(tokens: Sequence[Token], offset: int) -> int:
    """Index of the token containing ``offset`` (the last token at the end of the text); -1 if none."""
    return bisect_right(tokens, offset, key=_START) - 1


def token_at(document: Document, offset: int, kinds: Collection[TokenKind] = WORD_KINDS) -> Token | None:
    """The token of ``kinds`` (a word, by default) under the cursor: containing ``offset``, or ending there
    (cursor after a word). Only the cursor's line is looked at: a word never runs over a line break."""
    tokens = document.tokens_in(offset, offset)
    index = token_index(tokens, offset)
    for candidate in (index, index - 1):
        if 0 <= candidate < len(tokens):
            token = tokens[candidate]
            if token.kind in kinds and token.start <= offset <= token.end:
                return token
    return None


def line_prefix(positions: Positions, text: str, position: types.Position) -> str:
    """The text of the cursor's line up to the cursor."""
    offset = positions.offset(position)
    return text[positions.line_start(position.line) : offset]


def prefix_tokens(prefix: str, dialect: Dialect) -> list[Token]:
    """The core lexer's tokens of a line prefix; completion and signature help read the line being
    typed this way, without waiting for the whole file to be analysed again."""
    return [token for token in lex(prefix, dialect).tokens if token.kind is not TokenKind.NEWLINE]


def significant(tokens: list[Token]) -> list[Token]:
    return [token for token in tokens if token.kind not in TRIVIA]


def abbreviated(token: Token, words: Vocabulary) -> str | None:
    """The keyword ``token`` abbreviates (``SP``: SPEED, ``?``: PRINT); None for a keyword written in full,
    glued to its channel (``IN3``) or not, and for anything else."""
    if token.text in _SYMBOL_STATEMENTS:
        return _SYMBOL_STATEMENTS[token.text]
    if token.kind not in _KEYWORD_KINDS or not token.text.isalnum():
        return None
    name = words.keyword_name(token.text)
    spelled = token.text.upper()
    if name is None or spelled == name or (words.split_channel(spelled) and spelled.startswith(name)):
        return None
    return name
