"""Variables, labels and macros that are defined but never used.

Event handlers are called by the controller, so they are never unused. Nor is
a routine of nothing but DIMs: never calling it is the manual's way to keep
variables non-volatile (3.2.5).
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, own
from mintlang.analysis.traversal import Facts
from mintlang.semantic.events import event_of
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n
from mintlang.syntax.parser import Document


def check(facts: Facts) -> Iterator[Finding]:
    model = facts.model
    symbols = model.symbols
    for symbol in symbols.variables.values():
        if symbol.definitions and not symbol.references:
            first = symbol.definitions[0]
            yield Finding(
                first.unit, own("W103", first.span, f"variable '{first.spelling}' is declared but never used")
            )
    for symbol in symbols.macros.values():
        if symbol.definitions and not symbol.references:
            first = symbol.definitions[0]
            yield Finding(first.unit, own("W105", first.span, f"macro '{first.spelling}' is defined but never used"))
    dialect = model.program.dialect
    never_called = [
        (unit, identity, symbol)
        for unit, table in symbols.labels.items()
        for identity, symbol in table.items()
        if symbol.definitions and not symbol.references and event_of(symbol.name, dialect) is None
    ]
    declaring = _declaring_routines(model) if never_called else set()
    for unit, identity, symbol in never_called:
        if (unit, identity) not in declaring:
            first = symbol.definitions[0]
            detail = f"subroutine #{first.spelling} is never called by GOSUB or GOTO"
            yield Finding(first.unit, own("W104", first.span, detail))


def _declaring_routines(model: SemanticModel) -> set[tuple[Unit, str]]:
    """Labels whose routine only DIMs variables, then returns."""
    return {(unit, label.identity) for unit, document in model.documents() for label in _only_dims(document)}


def _only_dims(document: Document) -> Iterator[n.Name]:
    routines: list[tuple[n.Name, list[n.Statement]]] = []
    for line in document.lines:
        if line.label is not None:
            routines.append((line.label, []))
        if routines:
            routines[-1][1].extend(line.statements)
    for label, body in routines:
        if any(type(s) is n.Dim for s in body) and all(type(s) is n.Dim or _is_return(s) for s in body):
            yield label


def _is_return(statement: n.Statement) -> bool:
    return type(statement) is n.BlockWord and statement.word == "RETURN"  # type: ignore[union-attr]
