"""The rewrites' actions applied to one file: span edits in one pass, flags as ``REM MIGRATE:`` lines.

Everything outside an edited span is copied, never regenerated: line ends, case,
spacing and comments' text survive byte for byte. A flag becomes the migrator's
usual marker line above the flagged line, with its indentation and the file's own
line break (``REM`` is MintMT too, MT-1), or right below the AUTO or PROTECT line
that must open its file, saying it marks the line above (``marks_above``), unless
the lines next to it already carry it: that, and a MintMT text being left as it is
(``api``), make a second migration change nothing. The manual items are read back from the markers, as the v3 → v4
migration does, so markers a person has not dealt with yet stay listed.
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Sequence

from mintlang.diagnostics import LineIndex, Span
from mintlang.migrate.context import MARKER, marker_insertion, marker_text, marks_line_above
from mintlang.migrate.engine import FileOutcome
from mintlang.migrate.history import Edit, History
from mintlang.migrate.markers import manual_items
from mintlang.migrate.mintmt.source import Action, Flag, Rewrite, Source
from mintlang.migrate.model import Change

_NEWLINE = re.compile(r"\r\n|\r|\n")


def apply(source: Source, actions: Sequence[Action]) -> FileOutcome:
    """``source`` with ``actions`` done: each rewrite, and each flag's marker (once per line and text)."""
    text = source.text
    index = LineIndex(text)
    edits = [action for action in actions if isinstance(action, Rewrite)]
    markers = _markers(source, index, [action for action in actions if isinstance(action, Flag)])
    ordered = sorted(
        [*edits, *markers], key=lambda edit: (edit.span.start, edit.span.end, not marks_line_above(edit.text))
    )
    history = History()
    history.record(ordered)
    new_text, changes = _edited(text, index, ordered)
    manual = tuple(manual_items(new_text, history.origin, index))
    counts = Counter(change.rule for change in changes)
    counts.update(item.rule for item in manual)
    return FileOutcome(text, new_text, tuple(changes), manual, dict(sorted(counts.items())), ())


def _markers(source: Source, index: LineIndex, flags: list[Flag]) -> list[Edit]:
    """A marker line for each flag, above the line it flags (below the line opening the file, where
    ``marks_above`` reads it), unless already written there."""
    text = source.text
    newline = _NEWLINE.search(text)
    line_break = newline.group() if newline is not None else "\n"
    opening = source.opening
    made: list[Edit] = []
    seen: set[tuple[int, str]] = set()
    for flag in flags:
        number = index.position(flag.at).line
        above = opening is not None and number == opening.number
        marker = marker_text(flag.rule, " ".join(flag.reason.split()), above=above)
        start = index.line_start(number)
        if (start, marker) in seen:
            continue
        seen.add((start, marker))
        placed = marker_insertion(text, start, marker, line_break)
        if placed is not None:
            made.append(Edit(flag.rule, Span(placed[0], placed[0]), placed[1]))
    return made


def _edited(text: str, index: LineIndex, edits: list[Edit]) -> tuple[str, list[Change]]:
    """The text with ``edits`` (sorted, not overlapping) made, and a change for each rewrite."""
    parts: list[str] = []
    rewrites: list[tuple[Edit, int]] = []  # each rewrite with where its text starts in the new text
    position = 0
    written = 0
    for edit in edits:
        before = text[position : edit.span.start]
        parts += (before, edit.text)
        written += len(before)
        if not edit.text.lstrip().startswith(MARKER):
            rewrites.append((edit, written))
        written += len(edit.text)
        position = edit.span.end
    parts.append(text[position:])
    new_text = "".join(parts)
    new_index = LineIndex(new_text)
    changes = [
        Change(
            edit.rule,
            edit.span,
            index.position(edit.span.start).line,
            text[edit.span.start : edit.span.end],
            edit.text,
            new_index.position(at).line,
        )
        for edit, at in rewrites
    ]
    return new_text, changes
