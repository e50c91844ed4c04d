"""Variables, labels and macros that are defined but never used.

Event handlers are called by the controller, so they are never unused.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, own
from mintlang.analysis.traversal import Facts
from mintlang.semantic.events import event_of


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
    for table in symbols.labels.values():
        for symbol in table.values():
            if symbol.definitions and not symbol.references and event_of(symbol.name, model.program.dialect) is None:
                first = symbol.definitions[0]
                detail = f"subroutine #{first.spelling} is never called by GOSUB or GOTO"
                yield Finding(first.unit, own("W104", first.span, detail))
