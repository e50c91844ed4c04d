"""Constant values written to a keyword, checked against its range (error 3).

Only unscaled keywords are checked: for scaled ones the printed range applies
to the value times the scale factor, which is not known before run time
(10.2, Attributes).
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, mint_error
from mintlang.analysis.traversal import LineScope, Use
from mintlang.keyworddb import database
from mintlang.semantic.constants import constant_value
from mintlang.syntax import nodes as n


def each_line(scope: LineScope) -> Iterator[Finding]:
    db = database()
    controller, dialect = scope.controller.controller, scope.dialect
    for use in scope.facts.keyword_uses:
        if use.use is not Use.WRITE or not isinstance(use.statement, n.KeywordStatement):
            continue
        keyword = db.keywords_of(dialect).get(use.keyword.keyword)
        attributes = keyword.attributes_for(controller) if keyword else None
        if attributes is None or attributes.scaled or attributes.range is None:
            continue
        if attributes.range.minimum is None or attributes.range.maximum is None:
            continue
        for value in use.statement.values or ():
            number = constant_value(value, dialect)
            if value is None or number is None:
                continue
            # Whole-number ranges are not enforced: the manual prints "0 ≤ x ≤ 10000" for KDERIV
            # and then writes KDERIV = 1.5 in its example.
            if not attributes.range.holds(number):
                detail = f"{number:g} is outside the range of {use.keyword.keyword} ({attributes.range.text})"
                yield Finding(use.unit, mint_error(3, value.span, detail))
