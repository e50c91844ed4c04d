"""``REM text`` becomes ``' text``: MintMT's comment, at the start of a line or after code (004, 002).

Only the word ``REM`` is replaced, so the comment's text and the spacing after it
stay as they were; the checker reads its suppressions after either (``' mint: ignore[...]``).
The migrator's own ``REM MIGRATE:`` markers keep their ``REM``: it reads them by that word (MT-19).
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from mintlang.diagnostics import Span
from mintlang.migrate.mintmt.source import Action, Rewrite, Source

ID = "MT-COMMENT"
SUMMARY = "REM comments become ' comments"

_KEPT = re.compile(r"REM\s+MIGRATE:", re.IGNORECASE)


def find(source: Source) -> Iterator[Action]:
    text = source.text
    for line in source.lines:
        comment = line.comment
        if comment is None or text[comment.start : comment.start + 3].upper() != "REM":
            continue  # a v4 comment always starts with REM; kept for safety on odd input
        if _KEPT.match(text, comment.start):
            continue
        yield Rewrite(ID, Span(comment.start, comment.start + 3), "'")
