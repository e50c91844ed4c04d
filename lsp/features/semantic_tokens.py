"""Semantic tokens from the core's lexer: the editor colours what the compiler sees.

User names are told apart by the symbol table: macros, labels and arrays get
their own types, so a keyword abbreviation and a variable never look alike.
"""

from __future__ import annotations

from lsprotocol import types

from mintlang.diagnostics import Span
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Snapshot
from mintlang.syntax.nodes import identity
from mintlang.syntax.tokens import GRAMMAR_KEYWORDS, TokenKind

TOKEN_TYPES = ["keyword", "function", "enumMember", "variable", "macro", "number", "string", "comment", "operator"]
TOKEN_MODIFIERS: list[str] = []
_TYPE = {name: index for index, name in enumerate(TOKEN_TYPES)}
_BY_KIND: dict[TokenKind, int] = {
    **dict.fromkeys(GRAMMAR_KEYWORDS, _TYPE["keyword"]),
    TokenKind.KEYWORD: _TYPE["keyword"],
    TokenKind.FUNCTION: _TYPE["function"],
    TokenKind.CONSTANT: _TYPE["enumMember"],
    TokenKind.LABEL: _TYPE["function"],
    TokenKind.NUMBER: _TYPE["number"],
    TokenKind.STRING: _TYPE["string"],
    TokenKind.CHAR: _TYPE["string"],
    TokenKind.COMMENT: _TYPE["comment"],
    TokenKind.MACRO_BODY: _TYPE["macro"],
}
for _kind in (TokenKind.AND, TokenKind.OR, TokenKind.NOT, TokenKind.MOD, TokenKind.XOR):
    _BY_KIND[_kind] = _TYPE["operator"]


def encode(snapshot: Snapshot, within: Span | None = None) -> list[int]:
    """The relative five-integer encoding of every coloured token (of those in ``within``, if given)."""
    symbols = snapshot.model.symbols
    macros, labels = symbols.macros, symbols.labels[snapshot.unit]
    data: list[int] = []
    previous_line = previous_start = 0
    positions = snapshot.positions
    for token in snapshot.document.tokens:
        if within is not None and not within.start <= token.start < within.end:
            continue
        kind = _BY_KIND.get(token.kind)
        if token.kind is TokenKind.NAME:
            name = identity(token.text)
            if name in macros:
                kind = _TYPE["macro"]
            elif name in labels and name not in symbols.variables:
                kind = _TYPE["function"]
            else:
                kind = _TYPE["variable"]
        if kind is None or "\n" in token.text or "\r" in token.text:
            continue
        start, end = positions.position(token.start), positions.position(token.end)
        delta_line = start.line - previous_line
        delta_start = start.character - previous_start if delta_line == 0 else start.character
        data += [delta_line, delta_start, end.character - start.character, kind, 0]
        previous_line, previous_start = start.line, start.character
    return data


def register(server: MintServer) -> None:
    @server.feature(
        types.TEXT_DOCUMENT_SEMANTIC_TOKENS_FULL,
        types.SemanticTokensLegend(token_types=TOKEN_TYPES, token_modifiers=TOKEN_MODIFIERS),
    )
    def full(params: types.SemanticTokensParams) -> types.SemanticTokens:
        snapshot = server.snapshot(params.text_document.uri)
        return types.SemanticTokens(data=encode(snapshot) if snapshot is not None else [])

    @server.feature(
        types.TEXT_DOCUMENT_SEMANTIC_TOKENS_RANGE,
        types.SemanticTokensLegend(token_types=TOKEN_TYPES, token_modifiers=TOKEN_MODIFIERS),
    )
    def in_range(params: types.SemanticTokensRangeParams) -> types.SemanticTokens:
        """The visible part first: editors ask for it before the whole of a large file."""
        snapshot = server.snapshot(params.text_document.uri)
        if snapshot is None:
            return types.SemanticTokens(data=[])
        return types.SemanticTokens(data=encode(snapshot, snapshot.positions.span(params.range)))
