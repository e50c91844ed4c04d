"""Semantic tokens from the core's lexer: the editor colours what the compiler sees.

User names are told apart by the symbol table: macros and labels get their
own types, so a keyword abbreviation and a variable never look alike; a Mint
v3 word left in v4 code (``HMSPEED``, ``GAIN``) and declared nowhere is a
keyword, marked deprecated, not a variable.
Clients that ask for deltas get only what changed since their last result:
the encoding is relative, so typing on one line changes a few integers of
tens of thousands. Editors ask after every edit, so both are linear: tokens
are placed line by line in one pass, a long line with a non-ASCII character
costing its length once, and the two encodings are compared a block at a time.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterable, Sequence

from lsprotocol import types

from mintlang.analysis.rules.v3_keywords import is_v3_word
from mintlang.caching import LINES_KEPT, RecentCache
from mintlang.diagnostics import Span
from mintlang.dialect import Dialect
from mintlang.lsp.positions import columns
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Snapshot
from mintlang.syntax.lexer import LexedLine
from mintlang.syntax.lines import PhysicalLine
from mintlang.syntax.nodes import identity
from mintlang.syntax.parser import Document
from mintlang.syntax.tokens import GRAMMAR_KEYWORDS, MINTMT_BLOCK_WORDS, TokenKind

TOKEN_TYPES = ["keyword", "function", "enumMember", "variable", "macro", "number", "string", "comment", "operator"]
TOKEN_MODIFIERS = ["deprecated"]
_TYPE = {name: index for index, name in enumerate(TOKEN_TYPES)}
_DEPRECATED = 1 << 8  # a type with this bit set carries the deprecated modifier (bit 0 of the LSP's set)
_BY_KIND: dict[TokenKind, int] = {
    **dict.fromkeys(GRAMMAR_KEYWORDS | MINTMT_BLOCK_WORDS, _TYPE["keyword"]),
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
_NAME = TokenKind.NAME
_JUMPS = frozenset({TokenKind.GOSUB, TokenKind.GOTO})
_KEYWORD_WORDS = frozenset({TokenKind.KEYWORD, TokenKind.FUNCTION})  # a label may be named like one (000:1843)


_Coloured = tuple[int, int, int]  # start and end in its line, type


def encode(snapshot: Snapshot, within: Span | None = None) -> list[int]:
    """The relative five-integer encoding of every coloured token (of those starting in ``within``, if given).

    Line by line from the lexer: a physical line is an LSP line, its tokens
    come as parallel arrays (no token objects, no trivia), and its columns are
    converted to code units once, in a forward pass, and only if it is not ASCII.
    Within a line the encoding is relative to the line's first token, so each
    line's is kept while its text and the kinds of user names stay the same:
    after a keystroke only the edited line is coloured again.
    """
    name_types = _NameTypes(snapshot)
    encoding = snapshot.positions.encoding
    data: list[int] = []
    previous_line = 0
    if within is None:
        for number, (_, line) in _lines(snapshot.document, None):
            code = _line_code(line, snapshot.document.dialect, name_types, encoding)
            if code is not None:
                start, length, kind, rest = code
                data.extend((number - previous_line, start, length, *_split(kind)))
                data.extend(rest)
                previous_line = number
        return data
    previous_column = 0
    for number, (offset, line) in _lines(snapshot.document, within):
        tokens = [token for token in _coloured(line, name_types) if within.start <= offset + token[0] < within.end]
        if tokens and not line.text.isascii():
            tokens = _in_code_units(line.text, tokens, encoding)
        for start, end, kind in tokens:
            delta_start = start - previous_column if number == previous_line else start
            data.extend((number - previous_line, delta_start, end - start, *_split(kind)))
            previous_line, previous_column = number, start
    return data


def _split(kind: int) -> tuple[int, int]:
    """The LSP's token type and modifier set of a colour."""
    return kind & 0xFF, kind >> 8


_LineCode = tuple[int, int, int, tuple[int, ...]]  # the first token's column, length and type; the others encoded
_line_codes: RecentCache[tuple[str, Dialect, str, object], tuple[_LineCode | None]] = RecentCache(LINES_KEPT)


def _line_code(line: LexedLine, dialect: Dialect, name_types: _NameTypes, encoding: str) -> _LineCode | None:
    """The encoding of a line's coloured tokens, none when it has none (kept per line text, dialect, encoding
    and the way user names are coloured)."""
    key = (line.text, dialect, encoding, name_types.kinds)
    cached = _line_codes.get(key)
    if cached is not None:
        return cached[0]
    tokens = _coloured(line, name_types)
    if tokens and not line.text.isascii():
        tokens = _in_code_units(line.text, tokens, encoding)
    code: _LineCode | None = None
    if tokens:
        (start, end, kind), encoded, previous = tokens[0], [], tokens[0][0]
        for later, stop, later_kind in tokens[1:]:
            encoded.extend((0, later - previous, stop - later, *_split(later_kind)))
            previous = later
        code = (start, end - start, kind, tuple(encoded))
    _line_codes.put(key, (code,))
    return code


def _lines(document: Document, within: Span | None) -> Iterable[tuple[int, PhysicalLine]]:
    """The numbered physical lines that may hold tokens starting in ``within`` (all without it).

    Read from the lexed lines rather than ``document.tokens``: the lossless
    token stream is tens of thousands of objects built per version.
    """
    lines = document.physical
    if within is None:
        return enumerate(lines)
    indices = document.physical_between(within.start, within.end)
    return enumerate(lines[indices.start : indices.stop], indices.start)


class _NameTypes(dict[str, int]):
    """The type of each user name as written, looked up in the symbol table on first sight only (names
    recur on many lines): a macro, a label (unless also a variable), a v3 keyword or a variable."""

    def __init__(self, snapshot: Snapshot) -> None:
        super().__init__()
        symbols = snapshot.model.symbols
        self._macros, self._labels, self._variables = symbols.macros, symbols.labels[snapshot.unit], symbols.variables
        self._v4 = snapshot.document.dialect is Dialect.V4
        # v3 words a DIM makes the user's own variables (rare: only these need a look at the declarations)
        self._declared = frozenset(
            name for name, symbol in self._variables.items() if symbol.definitions and is_v3_word(symbol.name)
        )
        # Everything the colours of names depend on: the macros, the labels that are no variable, those v3 words.
        self.kinds = (frozenset(self._macros), frozenset(self._labels.keys() - self._variables.keys()), self._declared)

    def __missing__(self, text: str) -> int:
        name = identity(text)
        if name in self._macros:
            kind = _TYPE["macro"]
        elif name in self._labels and name not in self._variables:
            kind = _TYPE["function"]
        elif self._v4 and name not in self._declared and is_v3_word(text):
            kind = _TYPE["keyword"] | _DEPRECATED
        else:
            kind = _TYPE["variable"]
        self[text] = kind
        return kind


def _coloured(line: LexedLine, name_types: dict[str, int]) -> list[_Coloured]:
    """The tokens of ``line`` that get a colour, in order: trivia never do, but a REM comment does. The word
    after GOSUB or GOTO is a label, even where it is spelt like a keyword (``GOSUB home``) or a variable; the
    word after MintMT's Event names the event its block handles, coloured as a v4 handler's label (MT-13)."""
    found = []
    by_kind = _BY_KIND.get
    previous = None
    for kind, text, start in zip(line.kinds, line.texts, line.starts, strict=True):
        kind_type = name_types[text] if kind is _NAME else by_kind(kind)
        jumped_to = previous in _JUMPS and (kind in _KEYWORD_WORDS or kind_type == _TYPE["variable"])
        if jumped_to or (previous is TokenKind.EVENT and (kind is _NAME or kind in _KEYWORD_WORDS)):
            kind_type = _TYPE["function"]
        previous = kind
        if kind_type is not None:
            found.append((start, start + len(text), kind_type))
    if line.comment_start >= 0:
        found.append((line.comment_start, line.content_end, _TYPE["comment"]))
    return found


def _in_code_units(text: str, tokens: list[_Coloured], encoding: str) -> list[_Coloured]:
    """``tokens`` of the line ``text`` with their start and end counted in code units of ``encoding``."""
    edges = columns(text, [edge for start, end, _ in tokens for edge in (start, end)], encoding)
    return list(zip(edges[::2], edges[1::2], (kind for _, _, kind in tokens), strict=True))


_BLOCK = 256  # items compared at once when looking for where two encodings part


def difference(old: Sequence[int], new: Sequence[int]) -> list[types.SemanticTokensEdit]:
    """One edit turning ``old`` into ``new`` (none when they are equal): what lies between their
    common beginning and their common end is replaced."""
    limit = min(len(old), len(new))
    prefix = _common_prefix(old, new, limit)
    suffix = _common_suffix(old, new, limit - prefix)
    if prefix == len(old) == len(new):
        return []
    return [types.SemanticTokensEdit(prefix, len(old) - prefix - suffix, list(new[prefix : len(new) - suffix]))]


def _common_prefix(old: Sequence[int], new: Sequence[int], limit: int) -> int:
    """How many leading items (at most ``limit``) are equal: whole blocks are compared as slices, in C,
    and only the block where they part item by item, so an edit costs little over a copy of the arrays."""
    length = 0
    while length + _BLOCK <= limit and old[length : length + _BLOCK] == new[length : length + _BLOCK]:
        length += _BLOCK
    while length < limit and old[length] == new[length]:
        length += 1
    return length


def _common_suffix(old: Sequence[int], new: Sequence[int], limit: int) -> int:
    """How many trailing items (at most ``limit``) are equal, found as ``_common_prefix`` finds leading ones."""
    length = 0
    while (
        length + _BLOCK <= limit
        and old[len(old) - length - _BLOCK : len(old) - length] == new[len(new) - length - _BLOCK : len(new) - length]
    ):
        length += _BLOCK
    while length < limit and old[-1 - length] == new[-1 - length]:
        length += 1
    return length


class _Results:
    """The last tokens sent for each document, under the result id a delta request names.

    The encoding of the last snapshot is kept too: a snapshot is immutable, so
    asking again for an unchanged version (the whole after its visible range, a
    refresh) costs nothing. Only one, so that a closed document's analysis is
    not kept alive.
    """

    def __init__(self) -> None:
        self._last: dict[str, tuple[str, list[int]]] = {}
        self._ids = itertools.count(1)
        self._encoded: tuple[Snapshot, list[int]] | None = None

    def encoded(self, snapshot: Snapshot) -> list[int]:
        if self._encoded is None or self._encoded[0] is not snapshot:
            self._encoded = (snapshot, encode(snapshot))
        return self._encoded[1]

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
        data = results.encoded(snapshot)
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
