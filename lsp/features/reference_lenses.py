"""Code lenses: how often each label, variable, array and macro of a file is used, above its definition.

The count is resolved only for the lenses the editor shows, since counting
reads the texts of the macros too (a name written in a macro's text counts
once, where it is written). The lens is a title without a command: a count
to read, which every client shows as it is. This module owns the LSP's
code lens method, so the simulator's "Run" lens comes through it too.
"""

from __future__ import annotations

from lsprotocol import types

from mintlang.lsp.features import simulator
from mintlang.lsp.occurrences import written
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Snapshot
from mintlang.semantic.symbols import Symbol, SymbolKind
from mintlang.semantic.units import Unit


def lenses(snapshot: Snapshot) -> list[types.CodeLens]:
    """One unresolved lens on the first definition, in this file, of each of its symbols."""
    found = []
    for symbol in snapshot.model.symbols.all():
        definition = next((place for place in symbol.definitions if place.unit is snapshot.unit), None)
        if definition is not None:
            data = {"uri": snapshot.uri, "kind": symbol.kind.value, "name": symbol.identity}
            found.append(types.CodeLens(range=snapshot.positions.range(definition.span), data=data))
    return sorted(found, key=lambda lens: (lens.range.start.line, lens.range.start.character))


def _symbol(snapshot: Snapshot, kind: str, name: str) -> Symbol | None:
    table = snapshot.model.symbols
    if kind == SymbolKind.LABEL.value:
        return table.labels[snapshot.unit].get(name)
    found = table.macros.get(name) if kind == SymbolKind.MACRO.value else table.variables.get(name)
    return found if found is not None and found.kind.value == kind else None


def count(snapshot: Snapshot, symbol: Symbol) -> types.Command:
    """The lens's title: the uses written in the application, with where they are in its tooltip."""
    uses = [place for place in written(snapshot, symbol) if place not in symbol.definitions]
    title = f"{len(uses)} reference{'' if len(uses) == 1 else 's'}"
    in_files = {unit: sum(place.unit is unit for place in uses) for unit in (Unit.PROGRAM, Unit.CONFIGURATION)}
    where = [f"{number} in the {unit.value} file" for unit, number in in_files.items() if number]
    tooltip = f"{symbol.name}: {', '.join(where)}" if where else f"{symbol.name} is never used"
    return types.Command(title=title, command="", tooltip=tooltip)


def register(server: MintServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_CODE_LENS, types.CodeLensOptions(resolve_provider=True))
    def code_lens(params: types.CodeLensParams) -> list[types.CodeLens]:
        uri = params.text_document.uri
        snapshot = server.snapshot(uri)
        counts = lenses(snapshot) if snapshot is not None and snapshot.skipped is None else []
        return [*simulator.lenses(server, uri), *counts]

    @server.feature(types.CODE_LENS_RESOLVE)
    def resolve(lens: types.CodeLens) -> types.CodeLens:
        data = lens.data if isinstance(lens.data, dict) else {}
        snapshot = server.snapshot(str(data.get("uri", "")))
        symbol = _symbol(snapshot, str(data.get("kind")), str(data.get("name"))) if snapshot is not None else None
        if snapshot is not None and symbol is not None:
            lens.command = count(snapshot, symbol)
        return lens
