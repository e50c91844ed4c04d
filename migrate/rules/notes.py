"""Manual items that belong to the application rather than to a line: prologue notes.

Some v3 behaviour came from the hardware or from power-up defaults, not from a
statement, so there is no line to put a marker above. Such items go at the top
of the file that runs first (the configuration file when there is one), where
the missing configuration statement belongs, as ``REM MIGRATE:`` lines that
carry the v4 statement to write. Being comments, they keep the file compiling;
the report lists them like any other manual item (they flag the line below).
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence

from mintlang.migrate.context import MARKER, Context
from mintlang.migrate.rules.base import Replace
from mintlang.migrate.rules.declarations import insert_lines, prologue_file


def prologue_notes(context: Context, rule: str, notes: Sequence[str]) -> Iterator[Replace]:
    """One insertion of the ``REM MIGRATE: <rule>: <note>`` lines the prologue file lacks."""
    file = prologue_file(context)
    present = {line.strip() for line in file.text.splitlines()}
    lines = [line for line in (f"{MARKER} {rule}: {note}" for note in notes) if line not in present]
    if lines:
        yield insert_lines(file, lines)
