"""The manual items of a text: its ``REM MIGRATE:`` lines, each with the line it marks.

Items are read back from the migrated text rather than kept from the rules, so a
second run over migrated text reports what the first did, and markers a user has
not dealt with yet stay listed. A marker marks the first line below it that is not
a marker, or the first above it when it says so (``marks_above``: the one below a
PROTECT that opens its program); an application note (S-PROLOGUE, S-DEFAULTS: a
statement to fill in at the top of the application) marks no line, so its own line
is where to act.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

from mintlang.diagnostics import LineIndex, split_lines
from mintlang.migrate.context import MARKER_LINE, marks_above
from mintlang.migrate.model import ManualItem
from mintlang.migrate.rules import RULES

NOTE_RULES = frozenset(rule.id for rule in RULES if rule.notes)


def manual_items(text: str, origin: Callable[[int], int | None], source: LineIndex) -> Iterator[ManualItem]:
    """Every marker of ``text`` in line order; ``origin`` maps an offset of ``text`` to the
    original source (indexed by ``source``), or to None where the migrator wrote the text."""
    pending: list[tuple[int, str, str]] = []  # the markers waiting for the line they mark
    last: tuple[int, int] | None = None  # the number and offset of the last line that is not a marker

    def original(offset: int) -> int | None:  # asked only for marked lines
        start = origin(offset)
        return source.position(start).line if start is not None else None

    offset = 0
    for number, line in enumerate(split_lines(text, keepends=True), start=1):
        found = MARKER_LINE.match(line.rstrip("\r\n"))
        if found and found["rule"] in NOTE_RULES:
            yield ManualItem(found["rule"], number, found["reason"], None, note=True)
        elif found and marks_above(found) and last is not None:
            yield ManualItem(found["rule"], last[0], found["reason"], original(last[1]))
        elif found:
            pending.append((number, found["rule"], found["reason"]))
        else:
            if pending:  # the line they mark
                marked = original(offset)
                yield from (ManualItem(rule, number, reason, marked) for _, rule, reason in pending)
                pending = []
            last = (number, offset)
        offset += len(line)
    yield from (ManualItem(rule, number, reason, None) for number, rule, reason in pending)  # nothing below
