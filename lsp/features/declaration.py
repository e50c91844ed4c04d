"""Go to declaration: where the controller first declares a name, in compile order.

Definition lists every DIM, DEFINE or label line of a name (a variable the
configuration file and the program both DIM has two); declaration is the one
that creates it: the first in compile order, the configuration file's before
the program's. In Mint v3, where a write declares, that is the first write.
"""

from __future__ import annotations

from lsprotocol import types

from mintlang.lsp.features.navigation import locations
from mintlang.lsp.occurrences import symbol_at
from mintlang.lsp.server import MintServer
from mintlang.semantic.symbols import Occurrence, Symbol
from mintlang.semantic.units import Unit

_COMPILED = {Unit.CONFIGURATION: 0, Unit.PROGRAM: 1}


def declaring(symbol: Symbol) -> Occurrence | None:
    """The definition that declares ``symbol``: the first the compiler reaches."""
    return min(symbol.definitions, key=lambda place: (_COMPILED[place.unit], place.span.start), default=None)


def register(server: MintServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_DECLARATION)
    def declaration(params: types.DeclarationParams) -> list[types.Location] | None:
        snapshot = server.snapshot(params.text_document.uri)
        found = symbol_at(snapshot, snapshot.positions.offset(params.position)) if snapshot is not None else None
        first = declaring(found[0]) if found is not None else None
        return locations(snapshot, [first]) if snapshot is not None and first is not None else None
