"""Migrating a Mint v4 application (a program, its configuration file, or both) to MintMT."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace
from types import ModuleType

from mintlang.detection import detect_dialect
from mintlang.diagnostics import Severity, Span
from mintlang.dialect import Dialect
from mintlang.keyworddb.model import Controller
from mintlang.migrate import engine
from mintlang.migrate.mintmt import addressing, blocks, characters, comments, events, lengths, names, platforms
from mintlang.migrate.mintmt.apply import apply
from mintlang.migrate.mintmt.source import Source
from mintlang.migrate.mintmt.v3 import v3_uses
from mintlang.migrate.model import MigrationFailed, MigrationResult, unreadable
from mintlang.syntax.lines import MacroDefinition
from mintlang.syntax.parser import Document, parse
from mintlang.syntax.tokens import BYTE_ORDER_MARK

# One module per kind of rewrite, each with its ID, SUMMARY and find(source); the order is the report's.
REWRITES: tuple[ModuleType, ...] = (comments, characters, addressing, blocks, events, names)
# Then the checks of what the migration makes on the controller, each with its ID, SUMMARY and
# find(source, actions, controller).
CHECKS: tuple[ModuleType, ...] = (lengths, platforms)


def to_mintmt(
    source: str, *, config: str | None = None, controller: Controller | str = Controller.NEXTMOVE_PCI
) -> MigrationResult:
    """Rewrite a Mint v4 program (and its configuration file, whose result is ``.configuration``) in
    MintMT's syntax where the notes show it, flagging what they do not and the lines made too long for
    ``controller``. A file that already shows a form only MintMT has (``mintlang.detection``) comes back
    as it was, ``already_mintmt`` set; the other file of its application is migrated all the same (a
    program migrated alone leaves its configuration file in v4).
    Raises ``MigrationFailed`` on a Mint v3 application (``v3``): it is migrated to v4 first."""
    program_done = detect_dialect(source) is Dialect.MINTMT
    configuration_done = config is not None and detect_dialect(config) is Dialect.MINTMT
    if program_done and (config is None or configuration_done):
        configuration_as_it_was = engine.untouched(config) if config is not None else None
        return _result(engine.untouched(source), configuration_as_it_was, already=True)
    v3 = v3_uses(source, config)
    if v3.words:
        shown = ", ".join(v3.words)
        if v3.left_for_a_person:
            reason = f"still Mint v3 ({shown}) on lines mint-migrate flagged: deal with their REM MIGRATE items first"
            raise MigrationFailed(None, reason)
        raise MigrationFailed(None, f"this is Mint v3 ({shown}): migrate it to v4 first (mint-migrate without --to)")
    visible: frozenset[str] = frozenset()
    configuration: MigrationResult | None = None
    macros: Mapping[str, MacroDefinition] | None = None
    if config is not None:
        read = parse(config, Dialect.MINTMT if configuration_done else Dialect.V4)
        lexed = Source(config.removeprefix(BYTE_ORDER_MARK))
        configuration = _one(lexed, config, read, controller, done=configuration_done)
        visible, macros = lexed.macros, read.macros  # a program sees its configuration file's macros
    lexed = Source(source.removeprefix(BYTE_ORDER_MARK), visible)
    program = _one(lexed, source, parse(source, macros=macros), controller, done=program_done)
    return replace(program, configuration=configuration) if configuration is not None else program


def _one(source: Source, written: str, read: Document, controller: Controller | str, *, done: bool) -> MigrationResult:
    """One file of the application migrated, or as it was when it shows a MintMT form already (``done``)."""
    return _of(engine.untouched(written) if done else _migrated(source, written, read, controller), done)


def _migrated(source: Source, written: str, read: Document, controller: Controller | str) -> engine.FileOutcome:
    """``source`` (the text ``written`` without its byte-order mark, as the v3 -> v4 migration takes it)
    migrated, with the mark put back in front: a marker above the first line goes below it. ``read`` is
    ``written`` parsed as Mint v4: the lines it cannot read are the outcome's errors, as the v3 reader's are
    for a migration to v4 (the rewrites read tokens, and would pass them by unreported)."""
    actions = [action for rewrite in REWRITES for action in rewrite.find(source)]
    actions += [flag for check in CHECKS for flag in check.find(source, actions, controller)]
    outcome = apply(source, actions)
    index = read.line_index
    errors = tuple(
        unreadable(index.position(d.span.start).line, d) for d in read.diagnostics if d.severity is Severity.ERROR
    )
    outcome = replace(outcome, errors=errors)
    mark = BYTE_ORDER_MARK if written.startswith(BYTE_ORDER_MARK) else ""
    if not mark:
        return outcome
    changes = tuple(
        replace(change, span=Span(change.span.start + len(mark), change.span.end + len(mark)))
        for change in outcome.changes
    )
    return replace(outcome, source=mark + outcome.source, text=mark + outcome.text, changes=changes)


def _result(program: engine.FileOutcome, configuration: engine.FileOutcome | None, *, already: bool) -> MigrationResult:
    result = _of(program, already)
    return replace(result, configuration=_of(configuration, already)) if configuration is not None else result


def _of(outcome: engine.FileOutcome, already: bool) -> MigrationResult:
    return MigrationResult(
        outcome.source,
        outcome.text,
        outcome.changes,
        outcome.manual,
        outcome.counts,
        outcome.errors,
        already_mintmt=already,
    )
