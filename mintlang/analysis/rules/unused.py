"""Variables, labels and macros that are defined but never used.

Event handlers are called by the controller, so they are never unused. In Mint
v3 any assignment, FOR or INPUT declares a variable (001:1348-1360): that first
write is a use as well, as the write after a v4 DIM is, so only a DIM declares
a v3 variable that can go unused (``FOR i = 0 TO 10`` counting moves is no
unused ``i``, 001:5430-5436). Nor is a routine of nothing but DIMs: never
calling it is the manual's way to keep variables non-volatile (3.2.5); in v3 the
routine declares them by assigning them (``#non_volatile`` / ``my_var1 = 0`` /
``RETURN``, the guide's NONVOL1, 001:1408-1450). A
variable named in a statement that could not be parsed may be used there, and a
DEFINE that cannot name a macro (3005), or could not be parsed (``DEFINE 05``),
defines none: neither gets a second finding. Nor does an array indexed in square
brackets, as another language would (``arr[2] = 3``): Mint reads a keyword there
(round brackets index, square ones list axes, 000:1065-1066), and error 3007 is
the one finding to fix.
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from mintlang.analysis.findings import Finding, own
from mintlang.analysis.traversal import Facts
from mintlang.diagnostics import Span
from mintlang.dialect import Dialect
from mintlang.semantic.events import event_of, handler_meant
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n
from mintlang.syntax.parser import Document


def check(facts: Facts) -> Iterator[Finding]:
    model = facts.model
    symbols = model.symbols
    unused = [symbol for symbol in symbols.variables.values() if symbol.definitions and not symbol.references]
    if unused and model.program.dialect is Dialect.V3:
        dimmed = _declared_by_dim(facts)
        unused = [symbol for symbol in unused if (symbol.definitions[0].unit, symbol.definitions[0].span) in dimmed]
    broken = _names_in_broken_statements(facts) | _names_written_as_keywords(facts) if unused else set()
    for symbol in unused:
        if symbol.identity not in broken:
            first = symbol.definitions[0]
            detail = f"variable '{first.spelling}' is declared but never used"
            yield Finding(first.unit, own("W103", first.span, detail))
    not_macros = {
        (unit, line.span(statement.name.span))
        for unit, line, statement in facts.statements(n.Define)
        if not statement.name_is_word
    }
    unused_macros = [
        first
        for symbol in symbols.macros.values()
        if symbol.definitions and not symbol.references
        if ((first := symbol.definitions[0]).unit, first.span) not in not_macros
    ]
    broken = _broken_statements(facts) if unused_macros else []
    for first in unused_macros:
        if not any(unit is first.unit and span.start <= first.span.start < span.end for unit, span in broken):
            yield Finding(first.unit, own("W105", first.span, f"macro '{first.spelling}' is defined but never used"))
    dialect = model.program.dialect
    never_called = [
        (unit, identity, symbol)
        for unit, table in symbols.labels.items()
        for identity, symbol in table.items()
        if symbol.definitions and not symbol.references and event_of(symbol.name, dialect) is None
    ]
    declaring = _declaring_routines(model, dialect) if never_called else set()
    for unit, identity, symbol in never_called:
        if (unit, identity) not in declaring:
            first = symbol.definitions[0]
            detail = f"subroutine #{first.spelling} is never called by GOSUB or GOTO"
            if (meant := handler_meant(first.spelling, dialect)) is not None:
                detail += f": the event handler is #{meant}, with no leading zero"
            yield Finding(first.unit, own("W104", first.span, detail))


_DIM = frozenset({n.Dim})
_WORD = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


def _declared_by_dim(facts: Facts) -> set[tuple[Unit, Span]]:
    """Where a DIM names the variable it declares, as (unit, span in the file)."""
    return {
        (unit, line.span(statement.name.span))
        for unit, line, indexed in facts.lines.with_kinds(_DIM)
        for statement in indexed.statements
        if type(statement) is n.Dim
    }


def _broken_statements(facts: Facts) -> list[tuple[Unit, Span]]:
    """Where the statements that could not be parsed are written: a DEFINE among them (``DEFINE 05 = 1``, a
    name the lexer refuses) defines no macro, as one whose name is no word (3005) defines none. Found in
    one pass over the lines, however many macros go unused."""
    return [(unit, line.span(statement.span)) for unit, line, statement in facts.statements(n.SyntaxError_)]


def _names_in_broken_statements(facts: Facts) -> set[str]:
    sources = {unit: document.source for unit, document in facts.model.documents()}
    return {
        n.identity(word)
        for unit, line, statement in facts.statements(n.SyntaxError_)
        for word in _WORD.findall(sources[unit], *line.span(statement.span))
    }


def _names_written_as_keywords(facts: Facts) -> set[str]:
    """The names written where Mint reads a keyword (``arr[2]``): no DIM declares a keyword, so such a
    keyword is one the controller does not have, and the name is the user's."""
    return {n.identity(use.keyword.spelling) for _, use in facts.keyword_uses()}


def _declaring_routines(model: SemanticModel, dialect: Dialect) -> set[tuple[Unit, str]]:
    """Labels whose routine only declares variables, then returns."""
    return {
        (unit, label.identity)
        for unit, document in model.documents()
        for label in _only_declarations(document, dialect)
    }


def _only_declarations(document: Document, dialect: Dialect) -> Iterator[n.Name]:
    routines: list[tuple[n.Name, list[n.Statement]]] = []
    for line in document.placed:
        syntax = line.syntax
        if syntax.label is not None:
            routines.append((syntax.label, []))
        if routines:
            routines[-1][1].extend(syntax.statements)
    for label, body in routines:
        declares = [s for s in body if not _is_return(s)]
        if declares and all(_declares(s, dialect) for s in declares):
            yield label


def _declares(statement: n.Statement, dialect: Dialect) -> bool:
    """A DIM, or in v3 an assignment to a variable: "A variable declaration is any valid assignment" (001:1352)."""
    if type(statement) is n.Dim:
        return True
    return dialect is Dialect.V3 and type(statement) is n.Assignment and type(statement.target) is n.VariableRef


def _is_return(statement: n.Statement) -> bool:
    return type(statement) is n.BlockWord and statement.word == "RETURN"  # type: ignore[union-attr]
