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
from mintlang.records import record
from mintlang.semantic.index import NameUse, line_facts
from mintlang.semantic.symbols import Occurrence, Symbol, SymbolKind, SymbolTable
from mintlang.semantic.units import Unit
from mintlang.syntax.nodes import identity
from mintlang.syntax.parser import Document, parse
from mintlang.syntax.tokens import TRIVIA, TokenKind, in_a_word

_JUMPS = frozenset({TokenKind.GOSUB, TokenKind.GOTO})
# what GOSUB and GOTO take for a label's name (label_ref, grammar.lark): #home is a label as #worker is
_LABEL_REFERENCES = frozenset({TokenKind.NAME, TokenKind.KEYWORD, TokenKind.FUNCTION, TokenKind.NUMBER})


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


@record
class _Mention:
    occurrence: Occurrence
    label: bool  # the target of a GOSUB or GOTO, else a variable, array or macro


def _writes_in(document: Document, body: Span) -> frozenset[int]:
    """Where the names a macro's text writes start (assigned, a FOR's counter, an INPUT's target): the text
    read as a line of its own, as it runs where the macro is used (000:1452-1459)."""
    alone = parse(document.source[body.start : body.end], document.dialect, controller=document.context.controller)
    return frozenset(
        body.start + line.span(event.name.span).start
        for line in alone.placed
        for event in line_facts(Unit.PROGRAM, line).names
        if event.use is NameUse.WRITE
    )


def _mentions(unit: Unit, document: Document, offset: int | None = None) -> Iterator[_Mention]:
    """The user names written inside the bodies of this file's macros (of the body at ``offset``, if given)."""
    for definition in document.definitions:
        body = definition.body_span
        if body is None or (offset is not None and not body.start <= offset <= body.end):
            continue
        writes = _writes_in(document, body)
        tokens = document.tokens_in(body.start, body.end)
        index = max(token_index(tokens, body.start), 0)
        previous: TokenKind | None = None
        while index < len(tokens) and tokens[index].start < body.end:
            token = tokens[index]
            label = previous in _JUMPS
            named = token.kind in _LABEL_REFERENCES if label else token.kind is TokenKind.NAME
            if named and token.start >= body.start:
                occurrence = Occurrence(unit, Span(token.start, token.end), token.text, True, token.start in writes)
                yield _Mention(occurrence, label)
            if token.kind not in TRIVIA:
                previous = token.kind
            index += 1


def _mentioned_in(symbol: Symbol, unit: Unit) -> bool:
    """Whether a mention in ``unit``'s macros can mean ``symbol``: labels belong to one file, but a
    configuration file's macros are expanded in the program."""
    return symbol.kind is not SymbolKind.LABEL or unit is symbol.unit or unit is Unit.CONFIGURATION


def written(snapshot: Snapshot, symbol: Symbol) -> list[Occurrence]:
    """Where ``symbol``'s name is written, definitions first, then in the order of the files."""
    documents = dict(_documents(snapshot))
    found = [
        occurrence
        for occurrence in symbol.occurrences()
        if occurrence.unit in documents and _is_written(documents[occurrence.unit], occurrence)
    ]
    label = symbol.kind is SymbolKind.LABEL
    for unit, document in documents.items():
        if _mentioned_in(symbol, unit):
            found.extend(
                mention.occurrence
                for mention in _mentions(unit, document)
                if mention.label == label and identity(mention.occurrence.spelling) == symbol.identity
            )
    definitions = [occurrence for occurrence in found if occurrence in symbol.definitions]
    order = {Unit.CONFIGURATION: 0, Unit.PROGRAM: 1}
    others = sorted(
        (occurrence for occurrence in found if occurrence not in definitions),
        key=lambda occurrence: (order[occurrence.unit], occurrence.span.start),
    )
    return definitions + others


def _mentioned(snapshot: Snapshot, mention: _Mention) -> Symbol | None:
    table = snapshot.model.symbols
    name = identity(mention.occurrence.spelling)
    if mention.label:
        return table.labels[snapshot.unit].get(name) or table.labels[Unit.PROGRAM].get(name)
    # A macro replaces a variable of its name (3.5); in a macro's text it is the run-time error 2003,
    # but it still names that macro, not the undeclared variable its expansion records.
    return table.macros.get(name) or table.variables.get(name)


def symbol_at(snapshot: Snapshot, offset: int) -> tuple[Symbol, Occurrence] | None:
    """The user symbol whose name is written at ``offset`` of the snapshot's file."""
    document = snapshot.document
    table = snapshot.model.symbols
    for mention in _mentions(snapshot.unit, document, offset):
        span = mention.occurrence.span
        if span.start <= offset <= span.end:
            symbol = _mentioned(snapshot, mention)
            return (symbol, mention.occurrence) if symbol is not None else None
    word = _word_at(document.source, offset)
    for symbol in _named(table, word) if word else table.all():
        for occurrence in symbol.occurrences():
            span = occurrence.span
            here = occurrence.unit is snapshot.unit and span.start <= offset <= span.end
            if here and _is_written(document, occurrence):
                return symbol, occurrence
    return None


def _word_at(text: str, offset: int) -> str:
    """The name written at ``offset`` (or ending there), empty where none is."""
    start = end = offset
    while start > 0 and in_a_word(text[start - 1]):
        start -= 1
    while end < len(text) and in_a_word(text[end]):
        end += 1
    return text[start:end]


def _named(table: SymbolTable, word: str) -> Iterator[Symbol]:
    """The symbols a name written as ``word`` can be, in the order ``SymbolTable.all`` gives them:
    looked up, where going through every symbol's occurrences took time in proportion to the file."""
    name = identity(word)
    for symbols in (table.variables, table.macros, *table.labels.values()):
        symbol = symbols.get(name)
        if symbol is not None:
            yield symbol
