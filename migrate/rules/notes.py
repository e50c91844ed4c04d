"""Manual items that belong to the application rather than to a line: prologue notes.

Some v3 behaviour came from the hardware or from power-up defaults, not from a
statement, so there is no line to put a marker above. Such items go in the file
that runs first (the configuration file when there is one), where the missing
configuration statement belongs, as ``REM MIGRATE:`` lines that carry the v4
statement to write: at its top, or after its last ``CONFIG``, because a v4
CONFIG calls DEFAULT, which resets the inputs, enables and limits the notes
ask for (v4:8481-8482, v4:9006-9059). Being comments, they keep the file
compiling; the report lists them like any other manual item.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence

from mintlang.diagnostics import Span, lines_of
from mintlang.migrate.context import MARKER, Context, FileView
from mintlang.migrate.rules.base import Replace
from mintlang.migrate.rules.declarations import insert_lines, prologue_file
from mintlang.semantic.index import KeywordUse, Use


def prologue_notes(context: Context, rule: str, notes: Sequence[str]) -> Iterator[Replace]:
    """One insertion of the ``REM MIGRATE: <rule>: <note>`` lines the prologue file lacks."""
    file = prologue_file(context)
    present = {line.strip() for line in lines_of(file.text) if MARKER in line}  # a note's line holds one
    lines = [line for line in (f"{MARKER} {rule}: {note}" for note in notes) if line not in present]
    if lines:
        yield after_configuration(context, lines)


def after_configuration(context: Context, lines: Sequence[str]) -> Replace:
    """An insertion of whole lines in the file that runs first: after its last CONFIG, else at its top."""
    file = prologue_file(context)
    configs = [use.statement.span.start for use in _config_writes(context, file)]
    if not configs:
        return insert_lines(file, list(lines))
    end = file.line_end(max(configs))
    newline = file.newline
    if end == len(file.text):  # CONFIG on a last line without a line break
        return Replace(file.unit, Span(end, end), "".join(newline + line for line in lines))
    at = end + len(newline) if file.text.startswith(newline, end) else end + 1
    return Replace(file.unit, Span(at, at), "".join(line + newline for line in lines))


def _config_writes(context: Context, file: FileView) -> Iterator[KeywordUse]:
    for view, use in context.keyword_uses("CONFIG"):
        if view is file and use.use is Use.WRITE:
            yield use
