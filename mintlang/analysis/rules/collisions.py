"""Different spellings that the controller takes for one name.

Only the first ten characters of a name count (3.2.5): ``thisIsAVariable1``
and ``thisIsAVaraible2`` are one variable, which is rarely what the author
meant.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, own
from mintlang.analysis.traversal import Facts


def check(facts: Facts) -> Iterator[Finding]:
    model = facts.model
    for symbol in model.symbols.all():
        first = next(symbol.occurrences(), None)
        if first is None:
            continue
        reported: set[str] = {first.spelling.upper()}
        for occurrence in symbol.occurrences():
            spelling = occurrence.spelling.upper()
            if spelling in reported:
                continue
            reported.add(spelling)
            detail = (
                f"'{occurrence.spelling}' is the same {symbol.kind.value} as '{first.spelling}': "
                "only the first ten characters of a name count"
            )
            yield Finding(occurrence.unit, own("W108", occurrence.span, detail))
