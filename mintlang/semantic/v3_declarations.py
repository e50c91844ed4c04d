"""Mint v3's declarations: a variable read before anything declares it is "Undefined Variables".

v3 has no DIM for scalars: any assignment, FOR or INPUT declares a variable, at
compile time and in the order of the text, so a variable must be written before
any other reference to it in the text, "otherwise an undefined variable error will
be issued during compilation" (001:1352-1367, 1425-1429, 12971-12973). The array
COMMSON creates is declared by it (001:13217-13247). mint check reports each such read and
mint-run refuses to compile the program, as the controller does.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.semantic.model import SemanticModel
from mintlang.semantic.symbols import Occurrence
from mintlang.syntax import nodes as n

UNDEFINED_VARIABLE = 3001  # "Undefined Variables" (the v4 number of the same error)
COMMS = "COMMS"


def undefined_variables(model: SemanticModel) -> Iterator[Occurrence]:
    """Each reference to a variable that comes before its declaration in compile order."""
    comms_declared = _has_commson(model)
    for symbol in model.symbols.variables.values():
        if symbol.identity == COMMS and comms_declared:
            continue
        for reference in symbol.references:
            if not reference.declared_before and not reference.is_write:
                yield reference


def _has_commson(model: SemanticModel) -> bool:
    return any(
        type(statement) is n.KeywordStatement and statement.keyword.keyword == "COMMSON"
        for _, _, facts in model.lines
        for statement in facts.statements
    )
