"""The values the migrator hands out: rule descriptions, changes, manual items, results.

All frozen: a result can be cached by the language server and compared in tests.
Offsets are character offsets into decoded text (``mintlang.source`` decodes
files so that encoding the text again gives back the same bytes).
"""

from __future__ import annotations

import difflib
from collections.abc import Mapping
from dataclasses import field
from enum import StrEnum

from mintlang.diagnostics import Diagnostic, Edit, Position, Span, split_lines
from mintlang.records import record


class RuleClass(StrEnum):
    """How much a rule can be trusted to run unattended (migration spec, "Classes")."""

    MECHANICAL = "mechanical"  # provably equivalent token rewrite or insertion
    SEMI = "semi"  # automatic when the context is proven, a manual item otherwise
    MANUAL = "manual"  # only flags: the original stays, a REM MIGRATE line explains


class MigrationFailed(Exception):
    """A bug in the migrator met one application: a rule raised, or kept rewriting its own
    output; or the application is not in the dialect the migration reads (a Mint v3 file
    given to ``--to mintmt``). ``rule`` names it (None when reading the files failed), so the report can say
    which file and which rule, leave those files as they were and go on with the others."""

    def __init__(self, rule: str | None, reason: str) -> None:
        super().__init__(f"rule {rule} failed: {reason}" if rule else f"failed: {reason}")
        self.rule = rule
        self.reason = reason
        self.position: Position | None = None


class NotRead(MigrationFailed):
    """A file of an application that could not be read as Mint text, ``position`` where it stops being text
    (a NUL byte); or the other file of that application, which is not migrated without it (the two are read
    together, as the controller runs them). Not a bug: the reason alone says what to do."""

    def __init__(self, reason: str, position: Position | None = None) -> None:
        super().__init__(None, reason)
        self.position = position

    def __str__(self) -> str:
        return self.reason


class Phase(StrEnum):
    """The processing order of the migration spec (section 1); each phase re-parses."""

    ABBREVIATIONS = "abbreviations"  # several v3 abbreviations name other keywords in v4
    RENAMES = "renames"  # keywords, labels, constants, user names
    CONTEXT = "context"  # rewrites that need the statement around the keyword
    INSERTIONS = "insertions"  # DIM, AXES, input edge modes
    MANUAL = "manual"  # whatever is still Mint v3 gets a marker
    CHECK = "check"  # the result read as Mint v4 for the target: a line still invalid gets a marker


@record
class RuleInfo:
    """What ``--list-rules`` shows: id, class, phase, what it does and the manual's evidence;
    an optional rule runs only when asked for (``--with``)."""

    id: str
    rule_class: RuleClass
    phase: Phase
    summary: str
    evidence: str
    optional: bool = False


@record
class Change:
    """One rewrite: ``span`` and ``line`` locate the replaced text in the original source,
    ``migrated_line`` the line where its replacement starts in the migrated text."""

    rule: str
    span: Span
    line: int
    original: str
    replacement: str
    migrated_line: int


@record
class ManualItem:
    """Something left for the user. ``line`` is the line of the migrated text it marks (the
    one below its ``REM MIGRATE:`` line), ``original_line`` that line in the original (None
    when the migrator wrote the line). A ``note`` is about the whole application (a statement
    to fill in at its top): it marks no line, and ``line`` is the note's own."""

    rule: str
    line: int
    reason: str
    original_line: int | None
    note: bool = False


def unreadable(line: int, diagnostic: Diagnostic) -> str:
    """One of ``MigrationResult.errors``: ``line N: code message`` (the report reads the line back)."""
    return f"line {line}: {diagnostic.code} {diagnostic.message}"


@record
class MigrationResult:
    """The migration of one file; ``configuration`` holds that of the configuration file, if any."""

    source: str
    text: str
    changes: tuple[Change, ...]
    manual: tuple[ManualItem, ...]
    rule_counts: Mapping[str, int]
    errors: tuple[str, ...] = ()  # what the original's reader (v3; v4 to MintMT) finds in error: its unreadable lines
    configuration: MigrationResult | None = field(default=None, repr=False)
    already_v4: bool = False  # recognised as Mint v4 and left as it was (see ``recognise``)
    already_mintmt: bool = False  # ``--to mintmt``: recognised as MintMT and left as it was

    @property
    def changed(self) -> bool:
        return self.text != self.source

    def edits(self) -> tuple[Edit, ...]:
        """Minimal non-overlapping edits on ``source`` that produce ``text`` (for an editor's
        "migrate this file": one text edit per changed run of lines)."""
        old = split_lines(self.source, keepends=True)
        new = split_lines(self.text, keepends=True)
        starts = [0]
        for line in old:
            starts.append(starts[-1] + len(line))
        edits = []
        matcher = difflib.SequenceMatcher(None, old, new, autojunk=False)
        for tag, i1, i2, j1, j2 in matcher.get_opcodes():
            if tag != "equal":
                edits.append(Edit(Span(starts[i1], starts[i2]), "".join(new[j1:j2])))
        return tuple(edits)
