"""Call hierarchy: who jumps to a subroutine, and where a subroutine or the main program jumps to.

The parts of a file call one another: the main program (from the top to the
first label), each labelled section (from its label to the next) and each of
MintMT's Event and Startup blocks, which the program never runs into (MT-7): a
jump in one is the block's, wherever it stands. An item spans its part's
written lines, as the outline does: not the blank lines after it, nor the REM
lines that introduce the next label. A GOSUB or a GOTO is a call from the part
it stands in to the label it names; one written in a macro's text calls from
where the macro is used, where it runs. Event handlers have no caller in the
program: the controller calls them, which their detail says. Labels are per
file, so the hierarchy stays in the file it starts from.
"""

from __future__ import annotations

from collections.abc import Iterator

from lsprotocol import types

from mintlang.diagnostics import Span
from mintlang.lsp.features.symbols import (
    MintmtBlock,
    Section,
    after_line,
    jump_statements,
    label_kind,
    last_written,
    mintmt_blocks,
    sections,
)
from mintlang.lsp.occurrences import symbol_at
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Snapshot
from mintlang.records import record
from mintlang.semantic.symbols import Symbol, SymbolKind

MAIN = "main program"


@record
class Part:
    """The main program (``block`` and ``section`` None), a labelled section (offsets from its first line to the
    next part's) or a MintMT block (its own span). ``written`` is where its last written line ends: blank and
    comment lines up to the next part are in it (a cursor there is in it) but not shown as its own."""

    start: int
    end: int
    written: int
    block: MintmtBlock | None = None
    section: Section | None = None

    @property
    def label(self) -> Symbol | None:
        """The labelled section's label."""
        return self.section.symbol if self.section is not None else None

    @property
    def key(self) -> str | None:
        """What names the part in an item's data: its label's identity, or the block's outline name."""
        if self.block is not None:
            return self.block.name
        return self.label.identity if self.label is not None else None


@record
class Jump:
    """A GOSUB or GOTO: GOSUB and GOTO alike are calls here."""

    target: str  # the label's identity
    span: Span  # the label's name, or the macro use whose text holds the jump


def parts(snapshot: Snapshot) -> list[Part]:
    """The MintMT blocks, first, since the main program's or a section's offsets may hold one; then the parts of
    the snapshot's file in order, the main program only when something comes before a label."""
    positions = snapshot.positions
    blocks = [Part(block.span.start, block.span.end, block.span.end, block) for block in mintmt_blocks(snapshot)]
    labelled = sections(snapshot)
    starts = [positions.line_start(section.first_line) for section in labelled]
    ends = [*starts[1:], len(snapshot.document.source)] if starts else []
    found = [
        Part(start, end, after_line(snapshot, section.last_line), section=section)
        for section, start, end in zip(labelled, starts, ends, strict=True)
    ]
    top = starts[0] if starts else len(snapshot.document.source)
    main = Part(0, top, after_line(snapshot, last_written(snapshot, 0, positions.position(top).line - 1)))
    return [*blocks, main, *found] if top > 0 or not found else [*blocks, *found]


def jumps(snapshot: Snapshot) -> Iterator[Jump]:
    """Every GOSUB and GOTO of the snapshot's file, in order."""
    for line, statement in jump_statements(snapshot):
        yield Jump(statement.label.identity, line.span(statement.label.span))


def _containing(found: list[Part], offset: int) -> Part | None:
    return next((part for part in found if part.start <= offset < part.end), found[-1] if found else None)


def item(snapshot: Snapshot, part: Part) -> types.CallHierarchyItem:
    positions = snapshot.positions
    whole = positions.range(Span(part.start, part.written))
    data = {"uri": snapshot.uri, "label": part.key}
    if part.block is not None:
        event = part.block.is_event
        kind = types.SymbolKind.Event if event else types.SymbolKind.Constructor
        detail = "event handler: the controller calls it" if event else "power-up code: the controller runs it"
        selection = positions.range(part.block.selection)
        return types.CallHierarchyItem(part.block.name, kind, snapshot.uri, whole, selection, detail=detail, data=data)
    section = part.section
    if section is None:
        top = positions.range(Span(0, 0))
        return types.CallHierarchyItem(MAIN, types.SymbolKind.Module, snapshot.uri, whole, top, data=data)
    kind, detail = label_kind(section)
    detail = "event handler: the controller calls it" if section.is_event else detail
    selection = positions.range(section.symbol.definitions[0].span)
    name = f"#{section.symbol.name}"
    return types.CallHierarchyItem(name, kind, snapshot.uri, whole, selection, detail=detail, data=data)


def prepare(snapshot: Snapshot, offset: int) -> list[types.CallHierarchyItem]:
    """The label named at ``offset`` (a definition, GOSUB or GOTO), else the part the cursor is in."""
    found = parts(snapshot)
    named = symbol_at(snapshot, offset)
    if named is not None and named[0].kind is SymbolKind.LABEL:
        labelled = [part for part in found if part.key == named[0].identity]
        return [item(snapshot, part) for part in labelled]  # none for a label that is never defined
    part = _containing(found, offset)
    return [item(snapshot, part)] if part is not None else []


def incoming(snapshot: Snapshot, key: str | None) -> list[types.CallHierarchyIncomingCall]:
    """The parts that jump to the label ``key``, each with the places of its jumps."""
    found = parts(snapshot)
    callers: dict[int, list[types.Range]] = {}
    for jump in jumps(snapshot):
        caller = _containing(found, jump.span.start)
        if jump.target == key and caller is not None:
            callers.setdefault(found.index(caller), []).append(snapshot.positions.range(jump.span))
    return [
        types.CallHierarchyIncomingCall(from_=item(snapshot, found[index]), from_ranges=ranges)
        for index, ranges in sorted(callers.items(), key=lambda called: found[called[0]].start)
    ]


def outgoing(snapshot: Snapshot, key: str | None) -> list[types.CallHierarchyOutgoingCall]:
    """The labels the part ``key`` jumps to, each with the places of its jumps, in the order first jumped to."""
    found = parts(snapshot)
    part = next((candidate for candidate in found if candidate.key == key), None)
    targets = {candidate.key: candidate for candidate in found if candidate.label is not None}
    called: dict[str, list[types.Range]] = {}
    for jump in jumps(snapshot):
        if part is not None and _containing(found, jump.span.start) is part and jump.target in targets:
            called.setdefault(jump.target, []).append(snapshot.positions.range(jump.span))
    return [
        types.CallHierarchyOutgoingCall(to=item(snapshot, targets[target]), from_ranges=ranges)
        for target, ranges in called.items()
    ]


def register(server: MintServer) -> None:
    def origin(call_item: types.CallHierarchyItem) -> tuple[Snapshot, str | None] | None:
        """The analysis of the item's file and the label that names its part (None: the main program)."""
        data = call_item.data if isinstance(call_item.data, dict) else {}
        snapshot = server.snapshot(str(data.get("uri", call_item.uri)))
        label = data.get("label")
        return (snapshot, label if isinstance(label, str) else None) if snapshot is not None else None

    @server.feature(types.TEXT_DOCUMENT_PREPARE_CALL_HIERARCHY)
    def prepare_call_hierarchy(params: types.CallHierarchyPrepareParams) -> list[types.CallHierarchyItem] | None:
        snapshot = server.snapshot(params.text_document.uri)
        if snapshot is None or snapshot.skipped is not None:
            return None
        return prepare(snapshot, snapshot.positions.offset(params.position)) or None

    @server.feature(types.CALL_HIERARCHY_INCOMING_CALLS)
    def incoming_calls(params: types.CallHierarchyIncomingCallsParams) -> list[types.CallHierarchyIncomingCall]:
        found = origin(params.item)
        return incoming(*found) if found is not None else []

    @server.feature(types.CALL_HIERARCHY_OUTGOING_CALLS)
    def outgoing_calls(params: types.CallHierarchyOutgoingCallsParams) -> list[types.CallHierarchyOutgoingCall]:
        found = origin(params.item)
        return outgoing(*found) if found is not None else []
