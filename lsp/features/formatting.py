"""Formatting and range formatting: the core's house style (``mintlang.formatting``), one level of indentation
the editor's tab or spaces."""

from __future__ import annotations

from lsprotocol import types

from mintlang.formatting import formatting_edits
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Snapshot


def format_lines(snapshot: Snapshot, options: types.FormattingOptions, lines: range) -> list[types.TextEdit]:
    """One edit per changed line among 0-based ``lines``, so edits never overlap."""
    if snapshot.skipped is not None:
        return []
    indentation = " " * options.tab_size if options.insert_spaces else "\t"
    edits = formatting_edits(snapshot.model, snapshot.unit, indentation, lines)
    return [types.TextEdit(range=snapshot.positions.range(edit.span), new_text=edit.text) for edit in edits]


def register(server: MintServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_FORMATTING)
    def whole(params: types.DocumentFormattingParams) -> list[types.TextEdit]:
        snapshot = server.snapshot(params.text_document.uri)
        if snapshot is None:
            return []
        return format_lines(snapshot, params.options, range(snapshot.positions.line_count))

    @server.feature(types.TEXT_DOCUMENT_RANGE_FORMATTING)
    def part(params: types.DocumentRangeFormattingParams) -> list[types.TextEdit]:
        snapshot = server.snapshot(params.text_document.uri)
        if snapshot is None:
            return []
        start, end = params.range.start, params.range.end
        last = end.line - 1 if end.character == 0 and end.line > start.line else end.line  # whole lines selected
        count = snapshot.positions.line_count  # some clients send "everything" as a range past the end
        return format_lines(snapshot, params.options, range(min(start.line, count), min(last + 1, count)))
