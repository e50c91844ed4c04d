"""Linked editing: typing in a label's name edits its GOSUBs and GOTOs with it, and back.

Offered on a label's definition and on the names its jumps write (macro
texts included), when every one of them is spelt the same: the editor keeps
the ranges' texts equal, so two spellings of the label (``init``, ``INIT``)
get no linked ranges, and rename, which writes one spelling, is the tool.
Event handlers are left alone: the controller calls them by their names.
"""

from __future__ import annotations

from lsprotocol import types

from mintlang.diagnostics import Span
from mintlang.lsp.occurrences import symbol_at, written
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Snapshot
from mintlang.semantic.events import event_of
from mintlang.semantic.symbols import SymbolKind

# A label's name: a Mint name, or digits alone (any combination of alphanumeric characters, 000:1843; ``#123``)
WORD = r"[A-Za-z_][A-Za-z0-9_]*|[0-9]+"


def linked(snapshot: Snapshot, offset: int) -> list[Span] | None:
    """The spans of the label's name at ``offset`` and of every other place it is written, in this file."""
    found = symbol_at(snapshot, offset)
    if found is None or found[0].kind is not SymbolKind.LABEL or not found[0].definitions:
        return None
    label = found[0]
    if event_of(label.name, snapshot.settings.dialect) is not None:
        return None
    places = [place for place in written(snapshot, label) if place.unit is snapshot.unit]
    if len({place.spelling for place in places}) != 1:
        return None
    return [Span(place.span.end - len(place.spelling), place.span.end) for place in places]


def register(server: MintServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_LINKED_EDITING_RANGE)
    def linked_editing(params: types.LinkedEditingRangeParams) -> types.LinkedEditingRanges | None:
        snapshot = server.snapshot(params.text_document.uri)
        found = linked(snapshot, snapshot.positions.offset(params.position)) if snapshot is not None else None
        if snapshot is None or found is None:
            return None
        return types.LinkedEditingRanges(ranges=[snapshot.positions.range(span) for span in found], word_pattern=WORD)
