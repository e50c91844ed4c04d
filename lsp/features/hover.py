"""Hover: keywords (any spelling), predefined constants, user symbols, and Mint v3 words left in v4 code.

A keyword says which axes or channel it addresses where it is written (a macro
resolved) and what the configuration file sets for them; a variable its initial
value and the file that declares it; a label the remarks written above it.
"""

from __future__ import annotations

from lsprotocol import types

from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.lsp import addressed, describe, mintmt_words
from mintlang.lsp.lookup import token_at
from mintlang.lsp.occurrences import symbol_at
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Snapshot
from mintlang.syntax.parser import Document
from mintlang.syntax.tokens import Token, TokenKind

_COMMENT, _CHARACTER = frozenset({TokenKind.COMMENT}), frozenset({TokenKind.CHAR})
_SYMBOLS = frozenset({TokenKind.TILDE, TokenKind.COLON})  # manual entries written as a symbol: ~ and :


def _comment_keyword(document: Document, offset: int) -> Token | None:
    """The ``REM`` that starts a comment, as a keyword token, when ``offset`` is on it."""
    comment = token_at(document, offset, _COMMENT)
    if comment is not None and offset <= comment.start + len("REM"):
        return Token(TokenKind.KEYWORD, comment.text[: len("REM")], comment.start)
    return None


def _v3_word(snapshot: Snapshot, token: Token, declared: bool) -> str | None:
    """What a Mint v3 word v4 reads as an undeclared name (``HMSPEED``, ``GAIN``, ``_servo``) became."""
    if snapshot.settings.dialect is not Dialect.V4 or token.kind is not TokenKind.NAME or declared:
        return None
    return describe.v3_word(token.text, snapshot.model.controller)


def hover_text(snapshot: Snapshot, offset: int) -> tuple[str, int, int] | None:
    """Markdown for the word at ``offset`` and the span it describes."""
    character = token_at(snapshot.document, offset, _CHARACTER)
    if character is not None:
        return describe.character(character.text), character.start, character.end
    token = (
        token_at(snapshot.document, offset)
        or token_at(snapshot.document, offset, _SYMBOLS)
        or _comment_keyword(snapshot.document, offset)
    )
    if token is None:
        return None
    found = symbol_at(snapshot, offset)
    old = _v3_word(snapshot, token, found is not None and bool(found[0].definitions))
    if old is not None:
        return old, token.start, token.end
    if found is not None:
        return describe.symbol(snapshot, found[0]), found[1].span.start, found[1].span.end
    if snapshot.settings.dialect is Dialect.MINTMT and (block := mintmt_words.hover(snapshot.document, token)):
        text = block
    elif token.kind is TokenKind.CONSTANT:
        text = describe.constant(token.text, snapshot.settings.dialect, snapshot.settings.controller)
    elif token.kind in (TokenKind.NAME, TokenKind.LABEL):
        text = None
    elif snapshot.settings.dialect is Dialect.V3:
        word = database().lookup_v3(token.text)
        text = describe.v3_keyword(word) if word is not None else None
    else:
        settings = snapshot.settings
        word = settings.keyword(token.text)
        text = describe.keyword(word, settings.controller, token.text, settings.dialect) if word is not None else None
        here = addressed.hover_lines(snapshot, offset) if text is not None else []
        text = "\n".join([text, *here]) if text is not None else None
    return (text, token.start, token.end) if text is not None else None


def register(server: MintServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_HOVER)
    def hover(params: types.HoverParams) -> types.Hover | None:
        snapshot = server.snapshot(params.text_document.uri)
        if snapshot is None:
            return None
        found = hover_text(snapshot, snapshot.positions.offset(params.position))
        if found is None:
            return None
        text, start, end = found
        return types.Hover(
            contents=types.MarkupContent(kind=types.MarkupKind.Markdown, value=text),
            range=types.Range(start=snapshot.positions.position(start), end=snapshot.positions.position(end)),
        )
