"""What the analyser reports of a small program, as the per-rule tests compare it.

Each test states the complete list of diagnostics a small program gets, as (code, severity,
1-based line); line numbers in the tests' comments refer to the Mint v4 programming guide
(``../shared/seeds/000_*``).
"""

from __future__ import annotations

from collections.abc import Iterable

import mintlang
from mintlang import Diagnostic, Edit

ERROR, WARNING, INFO = "error", "warning", "info"


def found(source: str, *, controller: str = "nextmove-pci", config: str | None = None) -> list[tuple[str, str, int]]:
    """The program's diagnostics as (code, severity, line)."""
    index = mintlang.LineIndex(source)
    return [
        (d.code, d.severity.value, index.position(d.span.start).line)
        for d in mintlang.check(source, controller=controller, config=config)
    ]


def only(source: str, code: str, **options: str) -> Diagnostic:
    """The single diagnostic of ``code`` in the program."""
    (diagnostic,) = [d for d in mintlang.check(source, **options) if d.code == code]
    return diagnostic


def covered(source: str, diagnostic: Diagnostic) -> str:
    """The text a diagnostic points at."""
    return source[diagnostic.span.start : diagnostic.span.end]


def apply(source: str, edits: Iterable[Edit]) -> str:
    """``source`` with ``edits`` (not overlapping) made."""
    for edit in sorted(edits, key=lambda e: e.span.start, reverse=True):
        source = source[: edit.span.start] + edit.text + source[edit.span.end :]
    return source
