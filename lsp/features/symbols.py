"""Document outline (subroutines, event handlers, the labels inside them or the main program, MintMT's Event
and Startup blocks, variables, macros) and workspace symbols.

A label is an event handler when the controller calls it (000:10987) and a subroutine when a GOSUB names it
(000:1841-1850) or nothing jumps to it yet (the guide shows subroutines alone, 000:961), as ``mint check``'s flow
reads them; one only a GOTO names is a place in the code (000:11187-11188): a plain label, nested in the routine it
stands in before the RETURN that ends that routine outside any block.
"""

from __future__ import annotations

from bisect import bisect_left, bisect_right
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
    is_subroutine: bool  # a GOSUB of the file names it, or no jump at all (a subroutine not called yet)

    @property
    def is_routine(self) -> bool:
        """Whether it is entered by a call, a GOSUB's or the controller's, and returns: not a plain label."""
        return self.is_event or self.is_subroutine


def jump_statements(snapshot: Snapshot) -> Iterator[tuple[n.PlacedLine, n.Jump]]:
    """Every GOSUB and GOTO of the snapshot's file with its line, in order; one in a macro's text on the line
    that uses the macro, where it runs."""
    for unit, line, facts in snapshot.model.lines:
        if unit is snapshot.unit and n.Jump in facts.kinds:
            for statement in facts.statements:
                if type(statement) is n.Jump:
                    yield line, statement


def gosub_targets(snapshot: Snapshot) -> set[str]:
    """The identities of the labels a GOSUB of the file names: subroutines, whether written yet or not."""
    return {jump.label.identity for _, jump in jump_statements(snapshot) if jump.word == "GOSUB"}


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
    called = gosub_targets(snapshot)
    return [
        Section(
            label,
            first,
            last_written(snapshot, first, last),
            event_of(label.name, dialect) is not None,
            label.identity in called or not label.references,
        )
        for label, first, last in zip(labels, lines, ends, strict=True)
    ]


def last_written(snapshot: Snapshot, first: int, last: int) -> int:
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


def after_line(snapshot: Snapshot, line: int) -> int:
    """The offset just after the 0-based ``line`` and its line break (the end of the text after the last line)."""
    positions = snapshot.positions
    return positions.line_start(line + 1) if line + 1 < positions.line_count else len(snapshot.document.source)


def _returning_lines(snapshot: Snapshot) -> list[int]:
    """The lines (0-based, in order) with a RETURN of their own outside every block: where a routine ends, not a
    RETURN taken only when a condition holds (in an IF .. DO, or an IF .. THEN's statement)."""
    blocks = snapshot.model.structures[snapshot.unit].blocks
    return [
        line.number - 1
        for line in snapshot.document.placed
        if any(type(statement) is n.BlockWord and statement.word == "RETURN" for statement in line.syntax.statements)
        and not any(
            block.opener.line <= line.number and (block.closer is None or line.number <= block.closer.line)
            for block in blocks
        )
    ]


def _any_between(lines: list[int], first: int, last: int) -> bool:
    """Whether one of ``lines`` (in order) is from ``first`` to ``last``."""
    return bisect_left(lines, first) < bisect_right(lines, last)


def _routines(snapshot: Snapshot) -> Iterator[tuple[Section | None, list[Section]]]:
    """The sections in order, each plain label inside a routine with that routine: a routine with the labels it
    holds, or a plain label outside any (None) alone. A routine holds the labels after it up to its RETURN; a
    MintMT block (which the program never runs into) or the next routine ends it too."""
    returning = _returning_lines(snapshot)
    blocks = [block.opener.line - 1 for block in _mintmt_blocks_of(snapshot)]  # in order, as the file has them
    routine: Section | None = None
    held: list[Section] = []
    for section in sections(snapshot):
        if routine is not None and (section.is_routine or _any_between(blocks, routine.first_line, section.first_line)):
            yield routine, held
            routine, held = None, []
        if section.is_routine:
            routine = section
        elif routine is not None:
            held.append(section)
        else:
            yield None, [section]
        if routine is not None and _any_between(returning, section.first_line, section.last_line):
            yield routine, held
            routine, held = None, []
    if routine is not None:
        yield routine, held


def label_kind(section: Section) -> tuple[types.SymbolKind, str]:
    """The symbol kind and detail of a label's section; LSP has no kind for a label: a key names a place."""
    if section.is_event:
        return types.SymbolKind.Event, "event handler"
    if section.is_subroutine:
        return types.SymbolKind.Function, "subroutine"
    return types.SymbolKind.Key, "label"


def _label_symbol(
    snapshot: Snapshot, section: Section, last_line: int, children: list[types.DocumentSymbol]
) -> types.DocumentSymbol:
    """The outline's entry of a label, spanning its lines to ``last_line`` (0-based) and holding ``children``."""
    positions = snapshot.positions
    definition = section.symbol.definitions[0]
    whole = types.Range(
        start=types.Position(line=section.first_line, character=0),
        end=positions.position(after_line(snapshot, last_line)),
    )
    kind, detail = label_kind(section)
    return types.DocumentSymbol(
        name=f"#{section.symbol.name}",
        kind=kind,
        detail=detail,
        range=whole if whole.end.line >= whole.start.line else positions.range(definition.span),
        selection_range=positions.range(definition.span),
        children=children or None,
    )


def _document_symbols(snapshot: Snapshot) -> Iterator[types.DocumentSymbol]:
    positions = snapshot.positions
    for routine, held in _routines(snapshot):
        children = [_label_symbol(snapshot, label, label.last_line, []) for label in held]
        if routine is None:
            yield from children
        else:
            yield _label_symbol(snapshot, routine, held[-1].last_line if held else routine.last_line, children)
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
        for uri in dict.fromkeys([*server.opened(), *_workspace_programs(server)]):
            snapshot = server.snapshot(uri) or _from_disk(server, uri)
            if snapshot is None:
                continue
            label_kinds: dict[str, types.SymbolKind] | None = None  # worked out at the first label asked for
            for symbol in snapshot.model.symbols.all():
                if not symbol.definitions or query not in symbol.name.upper():
                    continue
                kind = _KINDS.get(symbol.kind, types.SymbolKind.Function)
                if symbol.kind is SymbolKind.LABEL:
                    if label_kinds is None:
                        label_kinds = {section.symbol.name: label_kind(section)[0] for section in sections(snapshot)}
                    kind = label_kinds.get(symbol.name, kind)  # as the outline names it
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
