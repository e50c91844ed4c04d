"""Document outline (subroutines, event handlers, MintMT's Event and Startup blocks, variables, macros) and
workspace symbols."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

from lsprotocol import types
from pygls.uris import from_fs_path, to_fs_path

from mintlang.diagnostics import Span
from mintlang.lsp.features.navigation import locations
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Snapshot
from mintlang.pairing import PROGRAM_SUFFIX
from mintlang.records import record
from mintlang.semantic.blocks import Block, BlockKind, Place
from mintlang.semantic.events import event_of
from mintlang.semantic.symbols import Symbol, SymbolKind
from mintlang.syntax import nodes as n
from mintlang.syntax.tokens import TRIVIA

MAX_FILES = 2000  # workspace symbols read at most this many programs from disk

_KINDS = {
    SymbolKind.VARIABLE: types.SymbolKind.Variable,
    SymbolKind.ARRAY: types.SymbolKind.Array,
    SymbolKind.MACRO: types.SymbolKind.Constant,
}


@record
class Section:
    """A labelled part of a file: from its label to its last line before the next label (0-based lines)."""

    symbol: Symbol
    first_line: int
    last_line: int
    is_event: bool


def sections(snapshot: Snapshot) -> list[Section]:
    """Each label's section, ending before the next label or the next of MintMT's Event and Startup blocks
    (which the program never runs into, MT-7)."""
    labels = sorted(
        (label for label in snapshot.model.symbols.labels[snapshot.unit].values() if label.definitions),
        key=lambda label: label.definitions[0].span.start,
    )
    lines = [snapshot.positions.position(label.definitions[0].span.start).line for label in labels]
    ends = [line - 1 for line in lines[1:]] + [snapshot.positions.line_count - 1] if lines else []
    blocks = [block.opener.line - 1 for block in _mintmt_blocks_of(snapshot)]  # Place lines count from 1
    ends = [
        min([end, *(line - 1 for line in blocks if first < line <= end)])
        for first, end in zip(lines, ends, strict=True)
    ]
    dialect = snapshot.settings.dialect
    return [
        Section(label, first, _last_written(snapshot, first, last), event_of(label.name, dialect) is not None)
        for label, first, last in zip(labels, lines, ends, strict=True)
    ]


def _last_written(snapshot: Snapshot, first: int, last: int) -> int:
    """``last`` moved up over blank and comment-only lines (REM, and MintMT's ``'``): the gap before the next
    section, and the comment that introduces it, are not part of this one."""
    positions, end = snapshot.positions, len(snapshot.document.source)
    while last > first:
        start = positions.line_start(last)  # the empty line after a final line break has no tokens of its own
        tokens = snapshot.document.tokens_in(start, start) if start < end else ()
        if not all(token.kind in TRIVIA for token in tokens):
            break
        last -= 1
    return last


def _document_symbols(snapshot: Snapshot) -> Iterator[types.DocumentSymbol]:
    positions = snapshot.positions
    for section in sections(snapshot):
        definition = section.symbol.definitions[0]
        end = positions.line_start(section.last_line + 1) if section.last_line + 1 < positions.line_count else None
        whole = types.Range(
            start=types.Position(line=section.first_line, character=0),
            end=positions.position(end) if end is not None else positions.position(len(snapshot.document.source)),
        )
        yield types.DocumentSymbol(
            name=f"#{section.symbol.name}",
            kind=types.SymbolKind.Event if section.is_event else types.SymbolKind.Function,
            detail="event handler" if section.is_event else "subroutine",
            range=whole if whole.end.line >= whole.start.line else positions.range(definition.span),
            selection_range=positions.range(definition.span),
        )
    yield from _mintmt_blocks(snapshot)
    table = snapshot.model.symbols
    for symbol in (*table.variables.values(), *table.macros.values()):
        definition = next((place for place in symbol.definitions if place.unit is snapshot.unit), None)
        if definition is not None:  # this file's own declaration, even when the other file has one too
            yield types.DocumentSymbol(
                name=symbol.name,
                kind=_KINDS[symbol.kind],
                detail=symbol.kind.value,
                range=positions.range(definition.span),
                selection_range=positions.range(definition.span),
            )


def _mintmt_blocks_of(snapshot: Snapshot) -> list[Block]:
    return [
        block
        for block in snapshot.model.structures[snapshot.unit].blocks
        if block.kind in (BlockKind.EVENT, BlockKind.STARTUP)
    ]


@record
class MintmtBlock:
    """One of MintMT's ``Event NAME`` and ``Startup`` blocks: its outline name, its span from the opener to the
    end of the closer's line (or of the file, when never closed), and the span of the event's name or of the
    word ``Startup``."""

    name: str
    span: Span
    selection: Span
    is_event: bool


def mintmt_blocks(snapshot: Snapshot) -> list[MintmtBlock]:
    """The file's Event and Startup blocks, in order."""
    blocks = _mintmt_blocks_of(snapshot)
    if not blocks:
        return []
    lines = {line.number: line for line in snapshot.document.placed}

    def span_of(place: Place) -> Span:
        line = lines[place.line]
        return line.span(n.flatten_statements(line.syntax.statements)[place.index].span)

    found = []
    for block in blocks:
        line = lines[block.opener.line]
        opener = n.flatten_statements(line.syntax.statements)[block.opener.index]
        event = opener.name if isinstance(opener, n.EventBlock) else None
        end = span_of(block.closer).end if block.closer is not None else len(snapshot.document.source)
        name = "Startup" if event is None else f"Event {event.text}"
        whole = Span(span_of(block.opener).start, end)
        found.append(MintmtBlock(name, whole, line.span((event or opener).span), event is not None))
    return found


def _mintmt_blocks(snapshot: Snapshot) -> Iterator[types.DocumentSymbol]:
    positions = snapshot.positions
    for block in mintmt_blocks(snapshot):
        yield types.DocumentSymbol(
            name=block.name,
            kind=types.SymbolKind.Event if block.is_event else types.SymbolKind.Constructor,
            detail="event handler" if block.is_event else "power-up code",
            range=positions.range(block.span),
            selection_range=positions.range(block.selection),
        )


def register(server: MintServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_DOCUMENT_SYMBOL)
    def outline(params: types.DocumentSymbolParams) -> list[types.DocumentSymbol]:
        snapshot = server.snapshot(params.text_document.uri)
        if snapshot is None:
            return []
        return sorted(_document_symbols(snapshot), key=lambda s: (s.range.start.line, s.range.start.character))

    @server.feature(types.WORKSPACE_SYMBOL)
    def workspace_symbols(params: types.WorkspaceSymbolParams) -> list[types.WorkspaceSymbol]:
        query = params.query.upper()
        found: dict[tuple[str, int, int], types.WorkspaceSymbol] = {}
        for uri in dict.fromkeys([*server.workspace.text_documents, *_workspace_programs(server)]):
            snapshot = server.snapshot(uri) or _from_disk(server, uri)
            if snapshot is None:
                continue
            for symbol in snapshot.model.symbols.all():
                if not symbol.definitions or query not in symbol.name.upper():
                    continue
                kind = _KINDS.get(symbol.kind, types.SymbolKind.Function)
                name = f"#{symbol.name}" if symbol.kind is SymbolKind.LABEL else symbol.name
                for location in locations(snapshot, symbol.definitions[:1]):
                    key = (location.uri, location.range.start.line, location.range.start.character)
                    found[key] = types.WorkspaceSymbol(name=name, kind=kind, location=location)
        return list(found.values())


def _workspace_programs(server: MintServer) -> list[str]:
    """URIs of the programs under the workspace folders, open or not (the first MAX_FILES, by path)."""
    roots = [to_fs_path(folder.uri) for folder in server.workspace.folders.values()]
    if not roots and server.workspace.root_path:
        roots = [server.workspace.root_path]
    paths: list[Path] = []
    for root in roots:
        if root is not None and Path(root).is_dir():
            paths.extend(path for path in Path(root).rglob("*") if path.suffix.lower() == PROGRAM_SUFFIX)
    return [from_fs_path(str(path)) or "" for path in sorted(paths)[:MAX_FILES]]


def _from_disk(server: MintServer, uri: str) -> Snapshot | None:
    """The analysis of a program the client has not opened, read from disk (cached by its text)."""
    text = server.read_text(uri)
    return server.analyses.snapshot(uri, text, None) if text is not None else None
