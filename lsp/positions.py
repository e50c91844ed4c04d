"""Character offsets of the core ↔ LSP positions (0-based lines, code units).

The core counts characters (code points); LSP columns count code units of the
negotiated encoding (UTF-16 unless the client offers another), so a character
outside the Basic Multilingual Plane counts twice in UTF-16 and non-ASCII
characters count up to four times in UTF-8. Lines break at ``\\r\\n``, ``\\r``
and ``\\n`` in both.
"""

from __future__ import annotations

from lsprotocol import types

from mintlang.diagnostics import LineIndex, Span


def _units(character: str, encoding: str) -> int:
    if encoding == types.PositionEncodingKind.Utf8:
        return len(character.encode("utf-8"))
    if encoding == types.PositionEncodingKind.Utf16:
        return 2 if ord(character) > 0xFFFF else 1
    return 1


class Positions:
    """Conversions for one text; built once per analysed version."""

    __slots__ = ("_encoding", "_index", "_line_count", "_plain", "_text")

    def __init__(self, text: str, encoding: str = types.PositionEncodingKind.Utf16) -> None:
        self._text = text
        self._index = LineIndex(text)
        self._line_count = self._index.position(len(text)).line
        self._encoding = encoding
        self._plain = text.isascii() or encoding == types.PositionEncodingKind.Utf32  # a unit per character

    @property
    def line_count(self) -> int:
        return self._line_count

    def line_start(self, line: int) -> int:
        """Offset of 0-based ``line``."""
        return self._index.line_start(max(0, min(line, self.line_count - 1)) + 1)

    def position(self, offset: int) -> types.Position:
        where = self._index.position(offset)
        column = where.column - 1
        if not self._plain:
            start = self._index.line_start(where.line)
            column = sum(_units(character, self._encoding) for character in self._text[start : start + column])
        return types.Position(line=where.line - 1, character=column)

    def range(self, span: Span) -> types.Range:
        return types.Range(start=self.position(span.start), end=self.position(span.end))

    def offset(self, position: types.Position) -> int:
        """Offset of an LSP position, clamped to its line and to the text."""
        if position.line >= self.line_count:
            return len(self._text)
        start = self.line_start(position.line)
        end = self._index.line_start(position.line + 2) if position.line + 1 < self.line_count else len(self._text)
        line = self._text[start:end].rstrip("\r\n")
        if self._plain:
            return start + min(position.character, len(line))
        units = 0
        for column, character in enumerate(line):
            if units >= position.character:
                return start + column
            units += _units(character, self._encoding)
        return start + len(line)

    def span(self, range_: types.Range) -> Span:
        return Span(self.offset(range_.start), self.offset(range_.end))
