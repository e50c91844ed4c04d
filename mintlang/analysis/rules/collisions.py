"""Different spellings that the controller takes for one name.

Only the first ten characters of a name count (3.2.5): ``thisIsAVariable1``
and ``thisIsAVaraible2`` are one variable, which is rarely what the author
meant. A second definition of a macro or label is already an error (3005,
3004) that says so, and gets no warning as well.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, own
from mintlang.analysis.traversal import Facts
from mintlang.semantic.symbols import SymbolKind

_DEFINED_ONCE = frozenset({SymbolKind.MACRO, SymbolKind.LABEL})


def check(facts: Facts) -> Iterator[Finding]:
    model = facts.model
    for symbol in model.symbols.all():
        first = next(symbol.occurrences(), None)
        if first is None:
            continue
        reported: set[str] = {first.spelling.upper()}
        redefinitions = symbol.definitions[1:] if symbol.kind in _DEFINED_ONCE else []
        for occurrence in symbol.occurrences():
            spelling = occurrence.spelling.upper()
            if spelling in reported:
                continue
            reported.add(spelling)
            if occurrence in redefinitions:
                continue
            detail = (
                f"'{occurrence.spelling}' is the same {symbol.kind.value} as '{first.spelling}': "
                "only the first ten characters of a name count"
            )
            yield Finding(occurrence.unit, own("W108", occurrence.span, detail))
