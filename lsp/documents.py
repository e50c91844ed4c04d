"""The open documents, kept with the LSP's line ends whatever characters they contain.

pygls' ``TextDocument`` finds lines with ``str.splitlines``, which also ends a
line at \\v, \\f, \\x1c-\\x1e, NEL (\\x85), U+2028 and U+2029; editors and
``Positions`` end lines only at ``\\n``, ``\\r\\n`` and ``\\r``, as the LSP
says. After a form feed of an old listing, or a NEL from a cp1252 file read as
latin-1, pygls would apply every incremental edit below it on the wrong line,
and the server's copy would no longer be the editor's text. pygls has no
setting for the document class: its ``Workspace`` makes documents in
``_create_text_document``, and its protocol makes the ``Workspace`` inside
``initialize``, so the server passes ``LspProtocol`` as its ``protocol_cls``.
"""

from __future__ import annotations

from collections.abc import Generator, Sequence
from typing import Any

from lsprotocol import types
from pygls.protocol import LanguageServerProtocol, lsp_method
from pygls.workspace import TextDocument, Workspace

from mintlang.diagnostics import LineIndex, line_starts, split_lines
from mintlang.lsp.positions import Positions
from mintlang.syntax.common import edited
from mintlang.syntax.moved import MovedOffsets, bisect_right


class LspTextDocument(TextDocument):
    """A pygls document whose lines, and so whose incremental edits, follow the LSP's line ends."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self._starts: tuple[str | None, Sequence[int] | None] = (None, None)  # a text, and its line starts

    @property
    def lines(self) -> Sequence[str]:
        """``splitlines(keepends=True)`` at the LSP's line ends only: the lines pygls' own position
        helpers index (``offset_at_position``, ``word_at_position``)."""
        return tuple(split_lines(self.source, keepends=True))

    def _apply_incremental_change(self, change: types.TextDocumentContentChangePartial) -> None:
        """Replace the change's range, found exactly as every feature finds positions: with ``Positions``
        in the negotiated encoding, clamping a column past its line to the line's end as the LSP says.

        The line starts of the text are kept from one change to the next, moved by each
        (``mintlang.syntax.moved``): finding them again costs time in proportion to the file."""
        source = self.source
        starts = self._starts[1] if self._starts[0] is source else None
        index = LineIndex(source, starts)
        positions = Positions(source, self.position_codec.encoding or types.PositionEncodingKind.Utf16, index)
        start, end = positions.offset(change.range.start), positions.offset(change.range.end)
        self._source = source[:start] + change.text + source[end:]
        self._starts = (self._source, _moved_starts(source, index, start, end, change.text))
        edited(source, self._source, start, end)  # the analysis need not compare the two texts to find the change


def _moved_starts(source: str, index: LineIndex, start: int, end: int, text: str) -> Sequence[int] | None:
    """The line starts after ``source[start:end]`` became ``text``, from ``index``, those of ``source``;
    None (found again when needed) where a ``\r`` is near, which may join a ``\n`` into one line end."""
    if "\r" in text or "\r" in source[max(0, start - 1) : end + 1]:
        return None
    starts = index.starts
    first = bisect_right(starts, start)  # the lines that start after the change's start, up to its end, go
    last = bisect_right(starts, end)
    added = [start + line for line in line_starts(text)[1:]]
    return MovedOffsets.spliced(starts, (first, last), added, len(text) - (end - start), 0)


class LspWorkspace(Workspace):
    """pygls' workspace, holding ``LspTextDocument``s."""

    def _create_text_document(
        self,
        doc_uri: str,
        source: str | None = None,
        version: int | None = None,
        language_id: str | None = None,
    ) -> LspTextDocument:
        return LspTextDocument(
            doc_uri,
            source=source,
            version=version,
            language_id=language_id,
            sync_kind=self._sync_kind,
            position_codec=self.position_codec,
        )


class LspProtocol(LanguageServerProtocol):
    """pygls' protocol, whose workspace is an ``LspWorkspace``."""

    @lsp_method(types.INITIALIZE)
    def lsp_initialize(self, params: types.InitializeParams) -> Generator[Any, Any, types.InitializeResult]:
        """pygls' initialize, then its workspace rebuilt as an ``LspWorkspace`` before the answer goes out.

        Clients open no document before that answer, so the rebuilt workspace, with the same root,
        folders and negotiated encoding, is the one every document lives in."""
        result = yield from super().lsp_initialize(params)
        made = self.workspace
        self._workspace = LspWorkspace(
            made.root_uri,
            self._server._text_document_sync_kind,
            list(made.folders.values()),
            made.position_encoding,
        )
        return result
