"""The manual's execution-speed advice: one axis by dot, not brackets.

``POS.1`` is smaller and faster than ``POS[1]`` (3.1.2); offered with a fix.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, own
from mintlang.analysis.traversal import LineScope
from mintlang.diagnostics import Edit, Fix
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Addressing
from mintlang.syntax import nodes as n


def each_line(scope: LineScope) -> Iterator[Finding]:
    db = database()
    for use in scope.facts.keyword_uses:
        selector = use.keyword.selector
        if selector is None or selector.dot or len(selector.items) != 1:
            continue
        item = selector.items[0]
        keyword = db.keywords_of(scope.dialect).get(use.keyword.keyword)
        if keyword is None or keyword.addressing is not Addressing.AXIS:
            continue
        if isinstance(item, n.Number | n.VariableRef):
            written = scope.syntax.text[item.span.start : item.span.end]
            value = item.text if isinstance(item, n.Number) else item.name.text
            # A macro needs a delimiter before it, or the dot is ignored: MOVER..xAxis (3.5)
            dotted = f".{written}" if written.upper() == value.upper() else f"..{written}"
            fix = Fix(f"Write {dotted}", (Edit(selector.span, dotted),), safe=True)
            detail = f"{use.keyword.spelling}{dotted} is faster and smaller than {use.keyword.spelling}[{written}]"
            yield Finding(use.unit, own("I201", selector.span, detail, fixes=(fix,)))
