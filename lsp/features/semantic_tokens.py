"""Semantic tokens from the core's lexer: the editor colours what the compiler sees.

User names are told apart by the symbol table: macros and labels get their
own types, so a keyword abbreviation and a variable never look alike.
Clients that ask for deltas get only what changed since their last result:
the encoding is relative, so typing on one line changes a few integers of
tens of thousands.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

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


def difference(old: Sequence[int], new: Sequence[int]) -> list[types.SemanticTokensEdit]:
    """One edit turning ``old`` into ``new`` (none when they are equal): what lies between their
    common beginning and their common end is replaced."""
    limit = min(len(old), len(new))
    prefix = 0
    while prefix < limit and old[prefix] == new[prefix]:
        prefix += 1
    suffix = 0
    while suffix < limit - prefix and old[-1 - suffix] == new[-1 - suffix]:
        suffix += 1
    if prefix == len(old) == len(new):
        return []
    return [types.SemanticTokensEdit(prefix, len(old) - prefix - suffix, list(new[prefix : len(new) - suffix]))]


class _Results:
    """The last tokens sent for each document, under the result id a delta request names."""

    def __init__(self) -> None:
        self._last: dict[str, tuple[str, list[int]]] = {}
        self._ids = itertools.count(1)

    def remember(self, uri: str, data: list[int]) -> str:
        result_id = str(next(self._ids))
        self._last[uri] = (result_id, data)
        return result_id

    def previous(self, uri: str, result_id: str) -> list[int] | None:
        last = self._last.get(uri)
        return last[1] if last is not None and last[0] == result_id else None

    def forget(self, uri: str) -> None:
        self._last.pop(uri, None)


def register(server: MintServer) -> None:
    results = _Results()

    @server.feature(
        types.TEXT_DOCUMENT_SEMANTIC_TOKENS_FULL,
        types.SemanticTokensLegend(token_types=TOKEN_TYPES, token_modifiers=TOKEN_MODIFIERS),
    )
    def full(params: types.SemanticTokensParams) -> types.SemanticTokens:
        uri = params.text_document.uri
        snapshot = server.snapshot(uri)
        if snapshot is None:
            results.forget(uri)
            return types.SemanticTokens(data=[])
        data = encode(snapshot)
        return types.SemanticTokens(data=data, result_id=results.remember(uri, data))

    @server.feature(types.TEXT_DOCUMENT_SEMANTIC_TOKENS_FULL_DELTA)
    def delta(params: types.SemanticTokensDeltaParams) -> types.SemanticTokens | types.SemanticTokensDelta:
        uri = params.text_document.uri
        previous = results.previous(uri, params.previous_result_id)
        answer = full(types.SemanticTokensParams(text_document=params.text_document))
        if previous is None or answer.result_id is None:
            return answer
        return types.SemanticTokensDelta(edits=difference(previous, answer.data), result_id=answer.result_id)

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
