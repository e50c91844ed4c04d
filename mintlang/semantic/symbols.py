"""The symbol table of a configuration file and a program file.

Names are identified as the controller identifies them: case-insensitive, first
ten characters significant (``identity``). Variables and macros of the
configuration are visible in the program; labels are not shared between the
two files. Declarations count in compile order (configuration first, then the
program, each top to bottom), so every reference records whether its name was
already declared when the compiler reached it.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping
from dataclasses import field
from enum import StrEnum
from typing import NamedTuple

from mintlang.diagnostics import Span
from mintlang.dialect import Dialect
from mintlang.records import record
from mintlang.semantic.index import LineFacts, NameEvent, NameUse
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n
from mintlang.syntax.parser import Document

__all__ = ["Occurrence", "Symbol", "SymbolKind", "SymbolTable", "Unit", "build_symbols"]


class SymbolKind(StrEnum):
    VARIABLE = "variable"
    ARRAY = "array"
    LABEL = "label"
    MACRO = "macro"


_BARE, _DECLARE, _WRITE = NameUse.BARE, NameUse.DECLARE, NameUse.WRITE
_new = tuple.__new__  # builds Span without its Python-level constructor


class Occurrence(NamedTuple):
    """One place a name is written: ``relative`` is its span in the line that starts at ``origin``.

    A name written in a line keeps the span of its node, which equal spans share, and the
    line's offset: a span and two integers of its own per name written were a twentieth of
    a check's memory. Made from a span in the file, ``origin`` is 0. A named tuple, made
    by ``tuple.__new__`` where the table is built: every check makes one per name written.
    """

    unit: Unit
    relative: Span
    spelling: str
    declared_before: bool  # the name was declared earlier in compile order
    is_write: bool = False
    origin: int = 0

    @property
    def span(self) -> Span:
        """Where it is in its file."""
        relative, origin = self.relative, self.origin
        return _new(Span, (relative.start + origin, relative.end + origin)) if origin else relative

    def written_in(self, source: str) -> bool:
        """Whether the name is written where it occurs in its file's ``source``, not brought there by a macro
        (whose name is written there instead): a fix that rewrites it must not rewrite the macro's use."""
        span = self.span
        return source[span.start : span.end] == self.spelling


@record(frozen=False)
class Symbol:
    """A user name with its definition and every reference.

    Mutable only while the table is being built; the table hands out no way
    to change it afterwards.
    """

    kind: SymbolKind
    identity: str
    unit: Unit
    definitions: list[Occurrence] = field(default_factory=list)  # DIMs, labels, DEFINEs
    references: list[Occurrence] = field(default_factory=list)
    array_size: int | None = None  # elements, when given by a constant

    @property
    def name(self) -> str:
        """The spelling of the first definition (or first use)."""
        first = self.definitions[0] if self.definitions else self.references[0]
        return first.spelling

    @property
    def definition(self) -> Occurrence | None:
        return self.definitions[0] if self.definitions else None

    def occurrences(self) -> Iterator[Occurrence]:
        yield from self.definitions
        yield from self.references


@record
class SymbolTable:
    variables: Mapping[str, Symbol]  # variables and arrays, shared by both files
    macros: Mapping[str, Symbol]  # shared by both files
    labels: Mapping[Unit, Mapping[str, Symbol]]  # per file

    def all(self) -> Iterator[Symbol]:
        yield from self.variables.values()
        yield from self.macros.values()
        for table in self.labels.values():
            yield from table.values()


class _Collector:
    """Replays what the syntax index saw, in compile order."""

    def __init__(self, dialect: Dialect) -> None:
        self.implicit_declarations = dialect is Dialect.V3  # v3: any assignment declares
        self.variables: dict[str, Symbol] = {}
        self.macros: dict[str, Symbol] = {}
        self.labels: dict[Unit, dict[str, Symbol]] = {Unit.CONFIGURATION: {}, Unit.PROGRAM: {}}

    def macros_and_labels(self, document: Document, unit: Unit) -> None:
        for definition in document.definitions:
            symbol = self.macros.setdefault(
                n.identity(definition.name), Symbol(SymbolKind.MACRO, n.identity(definition.name), unit)
            )
            symbol.definitions.append(Occurrence(unit, definition.name_span, definition.name, True))
        for expansion in document.expansions:
            symbol = self.macros.get(expansion.macro)
            if symbol is not None:
                spelling = document.source[expansion.span.start : expansion.span.end]
                symbol.references.append(Occurrence(unit, expansion.span, spelling, True))
        labels = self.labels[unit]
        for line in document.placed:
            label = line.syntax.label
            if label is not None:
                self._label(labels, label, unit).definitions.append(
                    Occurrence(unit, line.span(label.span), label.text, True)
                )

    def jump(self, unit: Unit, label: n.Name, span: Span) -> None:
        labels = self.labels[unit]
        defined = label.identity in labels and bool(labels[label.identity].definitions)
        self._label(labels, label, unit).references.append(Occurrence(unit, span, label.text, defined))

    def _label(self, labels: dict[str, Symbol], name: n.Name, unit: Unit) -> Symbol:
        return labels.setdefault(name.identity, Symbol(SymbolKind.LABEL, name.identity, unit))

    def declare(self, name: n.Name, origin: int, unit: Unit, size: n.Expression | None, *, array: bool = False) -> None:
        """A DIM, or in v3 the first write, in the line at ``origin``; ``array`` for an implicit v3 array (name(i))."""
        kind = SymbolKind.ARRAY if size is not None or array else SymbolKind.VARIABLE
        identity = name.identity  # one string for the table's key and the symbol's
        symbol = self.variables.get(identity)
        declared = symbol is not None and bool(symbol.definitions)
        if symbol is None:
            symbol = self.variables[identity] = Symbol(kind, identity, unit)
        if kind is SymbolKind.ARRAY:
            symbol.kind = SymbolKind.ARRAY
        if isinstance(size, n.Number) and size.value == int(size.value):
            symbol.array_size = int(size.value)
        symbol.definitions.append(_new(Occurrence, (unit, name.span, name.text, declared, True, origin)))

    def uses(self, unit: Unit, line: n.PlacedLine, events: tuple[NameEvent, ...]) -> None:
        """What one line does with names: declarations and references, in order.

        One loop for the line rather than a call per name: every check runs it for every name.
        """
        variables, origin = self.variables, line.origin
        for event in events:
            kind = event.use
            if kind is _BARE:
                continue
            name = event.name
            if kind is _DECLARE:
                self.declare(name, origin, unit, event.size)
                continue
            write = kind is _WRITE
            identity = n.identity(name.text)
            symbol = variables.get(identity)
            if symbol is None:
                if write and self.implicit_declarations:
                    self.declare(name, origin, unit, None, array=event.element)
                    continue
                kind_of = SymbolKind.ARRAY if event.element else SymbolKind.VARIABLE
                symbol = variables[identity] = Symbol(kind_of, identity, unit)
            occurrence = (unit, name.span, name.text, bool(symbol.definitions), write, origin)
            symbol.references.append(_new(Occurrence, occurrence))


def build_symbols(
    program: Document, configuration: Document | None, lines: Iterable[tuple[Unit, n.PlacedLine, LineFacts]]
) -> SymbolTable:
    """The symbol table of an application from its documents and the index of their lines, in compile order."""
    collector = _Collector(program.dialect)
    if configuration is not None:
        collector.macros_and_labels(configuration, Unit.CONFIGURATION)
    collector.macros_and_labels(program, Unit.PROGRAM)
    jumps: list[tuple[Unit, n.Name, Span]] = []
    for unit, line, facts in lines:
        if facts.names:
            collector.uses(unit, line, facts.names)
        if n.Jump in facts.kinds:
            for statement in facts.statements:
                if type(statement) is n.Jump:
                    jumps.append((unit, statement.label, line.span(statement.label.span)))
    for unit, label, span in jumps:
        collector.jump(unit, label, span)
    return SymbolTable(collector.variables, collector.macros, collector.labels)
