"""One shape for every place the manuals disagree with themselves.

Each record goes to ``conflicts.json``; the ones about a keyword also become
that keyword's ``notes``, so the two can never drift apart.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

Conflict = dict[str, Any]


def conflict(kind: str, subject: str, detail: str, lines: Iterable[int], **extra: Any) -> Conflict:
    return {"kind": kind, "subject": subject, "detail": detail, "lines": sorted(lines), **extra}


def sort_key(record: Conflict) -> tuple[str, str, list[int]]:
    return record["kind"], record["subject"], record["lines"]
