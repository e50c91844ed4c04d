"""What ``mint check`` finds in a source, as a reader sees it: each code with its place or the text it covers.

One helper serves every test that compares findings this way, so what "line", "column" and "the text
it covers" mean is written once.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Literal

import mintlang
from mintlang import Diagnostic, LineIndex

Field = Literal["code", "line", "column", "text", "severity", "fixes"]

_FIELDS: dict[Field, Callable[[str, LineIndex, Diagnostic], object]] = {
    "code": lambda source, index, d: d.code,
    "line": lambda source, index, d: index.position(d.span.start).line,
    "column": lambda source, index, d: index.position(d.span.start).column,
    "text": lambda source, index, d: source[d.span.start : d.span.end],
    "severity": lambda source, index, d: d.severity,
    "fixes": lambda source, index, d: len(d.fixes),
}


def placed(
    source: str,
    *fields: Field,
    found: Iterable[Diagnostic] | None = None,
    codes: str = "",
    dialect: str = "v4",
    controller: str = "nextmove-pci",
) -> list[tuple[object, ...]]:
    """``fields`` of each diagnostic whose code starts with ``codes``, in order.

    The diagnostics are ``found`` (a parse's, say), or else what ``mint check`` gives for ``dialect``
    and ``controller``.
    """
    index = LineIndex(source)
    diagnostics = mintlang.check(source, dialect=dialect, controller=controller) if found is None else found
    return [
        tuple(_FIELDS[field](source, index, d) for field in fields) for d in diagnostics if d.code.startswith(codes)
    ]


def placed_codes(source: str, dialect: str = "v4") -> list[tuple[object, ...]]:
    """Each finding's code, line and column."""
    return placed(source, "code", "line", "column", dialect=dialect)
