"""What ``mint check`` finds in a source, as a reader sees it: each code with its line and column."""

from __future__ import annotations

import mintlang


def placed_codes(source: str, dialect: str = "v4") -> list[tuple[str, int, int]]:
    index = mintlang.LineIndex(source)
    return [
        (d.code, index.position(d.span.start).line, index.position(d.span.start).column)
        for d in mintlang.check(source, dialect=dialect)
    ]
