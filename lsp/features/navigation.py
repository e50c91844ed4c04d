"""Go to definition, find references and document highlight for user symbols.

Identity is the controller's (case-insensitive, ten significant characters),
as resolved by the core's symbol table; macros and variables of the
configuration file are found from the program and back.
"""

from __future__ import annotations

from collections.abc import Iterable

from lsprotocol import types

from mintlang.lsp.occurrences import symbol_at, written
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Snapshot
from mintlang.semantic.symbols import Occurrence, Symbol


def locations(snapshot: Snapshot, occurrences: Iterable[Occurrence]) -> list[types.Location]:
    """LSP locations of occurrences in whichever file of the application holds them."""
    found = []
    for occurrence in occurrences:
        file = snapshot.files.get(occurrence.unit)
        if file is not None:
            found.append(types.Location(uri=file.uri, range=file.positions.range(occurrence.span)))
    return found


def register(server: MintServer) -> None:
    def lookup(uri: str, position: types.Position) -> tuple[Snapshot, Symbol] | None:
        """The analysed document and the symbol at ``position``, if both exist."""
        snapshot = server.snapshot(uri)
        found = symbol_at(snapshot, snapshot.positions.offset(position)) if snapshot is not None else None
        return (snapshot, found[0]) if snapshot is not None and found is not None else None

    @server.feature(types.TEXT_DOCUMENT_DEFINITION)
    def definition(params: types.DefinitionParams) -> list[types.Location] | None:
        found = lookup(params.text_document.uri, params.position)
        if found is None:
            return None
        snapshot, symbol = found
        return locations(snapshot, symbol.definitions) or None

    @server.feature(types.TEXT_DOCUMENT_REFERENCES)
    def references(params: types.ReferenceParams) -> list[types.Location] | None:
        found = lookup(params.text_document.uri, params.position)
        if found is None:
            return None
        snapshot, symbol = found
        wanted = written(snapshot, symbol)
        if not params.context.include_declaration:
            wanted = [occurrence for occurrence in wanted if occurrence not in symbol.definitions]
        return locations(snapshot, wanted)

    @server.feature(types.TEXT_DOCUMENT_DOCUMENT_HIGHLIGHT)
    def highlight(params: types.DocumentHighlightParams) -> list[types.DocumentHighlight] | None:
        found = lookup(params.text_document.uri, params.position)
        if found is None:
            return None
        snapshot, symbol = found
        return [
            types.DocumentHighlight(
                range=snapshot.positions.range(occurrence.span),
                kind=types.DocumentHighlightKind.Write
                if occurrence.is_write or occurrence in symbol.definitions
                else types.DocumentHighlightKind.Read,
            )
            for occurrence in written(snapshot, symbol)
            if occurrence.unit is snapshot.unit
        ]
