"""Array elements: indices known at compile time must lie in 1 .. size, and only
arrays have elements (error 2016, "Invalid index", 12.4).
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, mint_error
from mintlang.analysis.traversal import Facts
from mintlang.semantic.constants import constant_integer
from mintlang.semantic.symbols import SymbolKind


def check(facts: Facts) -> Iterator[Finding]:
    model = facts.model
    dialect = model.program.dialect
    for unit, element in facts.elements:
        symbol = model.symbols.variables.get(element.name.identity)
        if symbol is None or not symbol.definitions:
            continue  # undeclared: 3001 says so
        if symbol.kind is not SymbolKind.ARRAY:
            detail = f"'{element.name.text}' is a variable, not an array: declare it with DIM {symbol.name}(size)"
            yield Finding(unit, mint_error(2016, element.span, detail))
            continue
        if symbol.array_size is None:
            continue
        index = constant_integer(element.index, dialect)
        if index is not None and not 1 <= index <= symbol.array_size:
            detail = f"{element.name.text}({index}) is outside 1 to {symbol.array_size}"
            yield Finding(unit, mint_error(2016, element.index.span, detail))
