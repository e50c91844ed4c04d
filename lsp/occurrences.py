"""Where user names are written in the text, as navigation and rename need them.

The core records a name that comes from a macro's text at the place the macro
is used, so its diagnostics point where the user wrote the macro. Editing and
navigating need the text itself: those expanded uses are left out here, and
the names written inside ``DEFINE`` bodies are added, so renaming a variable a
macro mentions edits the macro's body and never the macro's uses.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.diagnostics import Span
from mintlang.lsp.lookup import token_index
from mintlang.lsp.workspace import Snapshot
from mintlang.semantic.symbols import Occurrence, Symbol
from mintlang.semantic.units import Unit
from mintlang.syntax.nodes import identity
from mintlang.syntax.parser import Document
from mintlang.syntax.tokens import TokenKind


def _documents(snapshot: Snapshot) -> Iterator[tuple[Unit, Document]]:
    model = snapshot.model
    if model.configuration is not None:
        yield Unit.CONFIGURATION, model.configuration
    if model.program is not None:
        yield Unit.PROGRAM, model.program


def _is_written(document: Document, occurrence: Occurrence) -> bool:
    """The occurrence's text is its name (not the name of a macro whose body holds it)."""
    text = document.source[occurrence.span.start : occurrence.span.end].lstrip("#")
    return identity(text) == identity(occurrence.spelling)


def _mentions(unit: Unit, document: Document, offset: int | None = None) -> Iterator[Occurrence]:
    """The user names written inside the bodies of this file's macros (of the body at ``offset``, if given)."""
    tokens = document.tokens
    for definition in document.definitions:
        body = definition.body_span
        if body is None or (offset is not None and not body.start <= offset <= body.end):
            continue
        index = max(token_index(document, body.start), 0)
        while index < len(tokens) and tokens[index].start < body.end:
            token = tokens[index]
            if token.kind is TokenKind.NAME and token.start >= body.start:
                yield Occurrence(unit, Span(token.start, token.end), token.text, True)
            index += 1


def written(snapshot: Snapshot, symbol: Symbol) -> list[Occurrence]:
    """Where ``symbol``'s name is written, definitions first, then in the order of the files."""
    documents = dict(_documents(snapshot))
    found = [
        occurrence
        for occurrence in symbol.occurrences()
        if occurrence.unit in documents and _is_written(documents[occurrence.unit], occurrence)
    ]
    if symbol.identity in snapshot.model.symbols.variables:
        for unit, document in documents.items():
            mentions = _mentions(unit, document)
            found.extend(mention for mention in mentions if identity(mention.spelling) == symbol.identity)
    definitions = [occurrence for occurrence in found if occurrence in symbol.definitions]
    order = {Unit.CONFIGURATION: 0, Unit.PROGRAM: 1}
    others = sorted(
        (occurrence for occurrence in found if occurrence not in definitions),
        key=lambda occurrence: (order[occurrence.unit], occurrence.span.start),
    )
    return definitions + others


def symbol_at(snapshot: Snapshot, offset: int) -> tuple[Symbol, Occurrence] | None:
    """The user symbol whose name is written at ``offset`` of the snapshot's file."""
    document = snapshot.document
    table = snapshot.model.symbols
    for mention in _mentions(snapshot.unit, document, offset):
        if mention.span.start <= offset <= mention.span.end:
            symbol = table.variables.get(identity(mention.spelling))
            return (symbol, mention) if symbol is not None else None
    for symbol in table.all():
        for occurrence in symbol.occurrences():
            span = occurrence.span
            here = occurrence.unit is snapshot.unit and span.start <= offset <= span.end
            if here and _is_written(document, occurrence):
                return symbol, occurrence
    return None
