"""Array indices known at compile time must lie in 1 .. size (error 2016)."""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, mint_error
from mintlang.analysis.traversal import statements
from mintlang.semantic.constants import constant_integer
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.symbols import SymbolKind
from mintlang.syntax import nodes as n


def check(model: SemanticModel) -> Iterator[Finding]:
    dialect = model.program.dialect
    for unit, _, statement in statements(model):
        elements = [node for node in n.expressions_of(statement) for node in n.walk_expression(node)]
        if isinstance(statement, n.Assignment | n.Input) and isinstance(statement.target, n.ElementRef):
            elements.append(statement.target)
        for element in elements:
            if not isinstance(element, n.ElementRef):
                continue
            symbol = model.symbols.variables.get(element.name.identity)
            if symbol is None or symbol.kind is not SymbolKind.ARRAY or symbol.array_size is None:
                continue
            index = constant_integer(element.index, dialect)
            if index is not None and not 1 <= index <= symbol.array_size:
                detail = f"{element.name.text}({index}) is outside 1 to {symbol.array_size}"
                yield Finding(unit, mint_error(2016, element.index.span, detail))
