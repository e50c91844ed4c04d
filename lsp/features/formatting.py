"""Formatting and range formatting: the core's house style (``mintlang.formatting``). One level of indentation
is the project's where its settings file's ``[format]`` table sets one, so that the editor writes what
``mint format --check`` accepts in CI; else the editor's tab or spaces."""

from __future__ import annotations

from pathlib import Path

from lsprotocol import types
from pygls.uris import to_fs_path

from mintlang.formatting import first_syntax_error, formatting_edits, project_indent_unit
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Snapshot
from mintlang.settings import SettingsError, project_for


def format_lines(snapshot: Snapshot, options: types.FormattingOptions, lines: range) -> list[types.TextEdit]:
    """One edit per changed line among 0-based ``lines``, so edits never overlap; none in a text with a syntax
    error, as ``mint format`` leaves it."""
    if snapshot.skipped is not None or first_syntax_error(snapshot.document) is not None:
        return []
    indentation = _project_indentation(snapshot.uri) or (" " * options.tab_size if options.insert_spaces else "\t")
    edits = formatting_edits(snapshot.model, snapshot.unit, indentation, lines)
    return [types.TextEdit(range=snapshot.positions.range(edit.span), new_text=edit.text) for edit in edits]


def _project_indentation(uri: str) -> str | None:
    """The indentation the settings file above the document sets, if any (a bad settings file sets none: the
    diagnostics say what is wrong with it)."""
    path = to_fs_path(uri) if uri.startswith("file:") else None
    try:
        project = project_for(Path(path)) if path is not None else None
    except SettingsError:
        return None
    return project_indent_unit(project.tool("format").values) if project is not None else None


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
