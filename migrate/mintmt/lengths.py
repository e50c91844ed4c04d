"""A line the rewrites take past the controller's 255 characters is flagged: split it.

A v4 line holds 255 characters (000:254-256), and the rewrites lengthen lines:
``.0`` becomes ``(0)``, ``'A'`` becomes ``65``, ``THEN`` is added. A line that was
within the limit and is not after the rewrites gets a manual item, as the v3 to v4
migration's X-CHECK gives one; a line already too long in v4 is the checker's to
report (W111), not the migration's.
"""

from __future__ import annotations

from bisect import bisect_right
from collections import Counter
from collections.abc import Iterable, Iterator

from mintlang.controllers import profile
from mintlang.keyworddb.model import Controller
from mintlang.migrate.mintmt.source import Action, Flag, Rewrite, Source

ID = "MT-LENGTH"
SUMMARY = "a line the rewrites take past the controller's 255 characters is flagged (split it)"


def find(source: Source, actions: Iterable[Action], controller: Controller | str) -> Iterator[Flag]:
    """A flag on each line of ``source`` that ``actions``' rewrites make longer than ``controller`` takes."""
    limit = profile(controller).max_line_length
    lines = source.lines
    offsets = [line.offset for line in lines]
    growth: Counter[int] = Counter()
    for action in actions:
        if isinstance(action, Rewrite):
            start, end = action.span
            growth[bisect_right(offsets, start) - 1] += len(action.text) - (end - start)
    for index, grown in sorted(growth.items()):
        line = lines[index]
        length = line.lexed.content_end
        if length <= limit < length + grown:
            reason = f"line of {length + grown} characters in MintMT: the controller takes {limit}; split it"
            yield Flag(ID, line.offset, reason)
