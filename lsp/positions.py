"""Character offsets of the core ↔ LSP positions (0-based lines, code units).

The core counts characters (code points); LSP columns count code units of the
negotiated encoding (UTF-16 unless the client offers another), so a character
outside the Basic Multilingual Plane counts twice in UTF-16 and non-ASCII
characters count up to four times in UTF-8. Lines break at ``\\r\\n``, ``\\r``
and ``\\n`` in both.
"""

from __future__ import annotations

import re
from collections.abc import Iterable

from lsprotocol import types

from mintlang.diagnostics import LineIndex, Span

_BEYOND_ASCII = re.compile(r"[^\x00-\x7f]")  # two to four UTF-8 units
_BEYOND_BMP = re.compile(r"[\U00010000-\U0010ffff]")  # two UTF-16 units


def columns(line: str, offsets: Iterable[int], encoding: str) -> list[int]:
    """Columns in code units of the character ``offsets`` (not decreasing) within ``line``.

    One forward pass that adds, to each offset, the extra units of the wide
    characters before it: the tokens of a line cost its length once, where a
    ``Positions.position`` per token would convert it from its start each time.
    """
    wide = _wide(encoding)
    if wide is None or line.isascii():
        return list(offsets)
    extras = [(match.start(), _length(match.group(), encoding) - 1) for match in wide.finditer(line)]
    found: list[int] = []
    extra = passed = 0
    for offset in offsets:
        while passed < len(extras) and extras[passed][0] < offset:
            extra += extras[passed][1]
            passed += 1
        found.append(offset + extra)
    return found


def _wide(encoding: str) -> re.Pattern[str] | None:
    """The characters that take more than one code unit of ``encoding`` (none in UTF-32)."""
    if encoding == types.PositionEncodingKind.Utf8:
        return _BEYOND_ASCII
    if encoding == types.PositionEncodingKind.Utf16:
        return _BEYOND_BMP
    return None


# Codec and bytes per code unit of each encoding: text measured by encoding it, at the codec's speed.
_CODECS = {types.PositionEncodingKind.Utf8: ("utf-8", 1), types.PositionEncodingKind.Utf16: ("utf-16-le", 2)}


def _length(text: str, encoding: str) -> int:
    """``text``'s length in code units of ``encoding``."""
    codec, size = _CODECS.get(encoding, ("", 0))
    return len(text.encode(codec, errors="surrogatepass")) // size if codec else len(text)


def _characters(line: str, units: int, encoding: str) -> int:
    """How many characters of ``line`` the first ``units`` code units reach; a unit inside a character
    counts the whole character, and units past the end stop there."""
    codec, size = _CODECS.get(encoding, ("", 0))
    if not codec:
        return min(units, len(line))
    head = line.encode(codec, errors="surrogatepass")[: units * size].decode(codec, errors="ignore")  # drops a cut one
    reached = len(head)
    return reached + 1 if _length(head, encoding) < units and reached < len(line) else reached


class Positions:
    """Conversions for one text; built once per analysed version."""

    __slots__ = ("_encoding", "_index", "_line_count", "_plain", "_text")

    def __init__(
        self, text: str, encoding: str = types.PositionEncodingKind.Utf16, index: LineIndex | None = None
    ) -> None:
        """``index`` is one already made for ``text`` (its parsed document's)."""
        self._text = text
        self._index = index or LineIndex(text)
        self._line_count = self._index.position(len(text)).line
        self._encoding = encoding
        self._plain = text.isascii() or encoding == types.PositionEncodingKind.Utf32  # a unit per character

    @property
    def encoding(self) -> str:
        """The negotiated position encoding, for callers that convert columns themselves."""
        return self._encoding

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
            column = _length(self._text[start : start + column], self._encoding)
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
        return start + _characters(line, position.character, self._encoding)

    def span(self, range_: types.Range) -> Span:
        return Span(self.offset(range_.start), self.offset(range_.end))
