"""POW given an index from 0 to 1 on NextMove (W121).

POW(x, y) returns x to the power y (000:15151-15155); on NextMove the index must be below 0
or above 1 (000:15163), a restriction the other controllers do not have. The guide names no
error for such an index, so what the controller answers is not known: the toolchain warns
where the index is known before the program runs (``held_value``), and mint-run works the
power out as on the other controllers (runtime/BEHAVIOUR.md, NM-5).
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, own
from mintlang.analysis.traversal import LineScope
from mintlang.keyworddb.model import NEXTMOVES
from mintlang.semantic.constants import held_value


def each_line(scope: LineScope) -> Iterator[Finding]:
    controller = scope.controller
    if controller.controller not in NEXTMOVES:
        return
    for call in scope.facts.calls:
        if call.function == "POW" and len(call.arguments) == 2:  # another count is the functions rule's 2003
            index = call.arguments[1]
            value = held_value(index, scope.dialect)
            if value is not None and 0 <= value <= 1:
                detail = f"POW's index is {value:.15g}: on {controller.title} it must be below 0 or above 1"
                yield Finding(scope.unit, own("W121", index.span, detail))
