"""Migrating a Mint v4 application (a program, its configuration file, or both) to MintMT."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import replace
from types import ModuleType

from mintlang.detection import detect_dialect
from mintlang.dialect import Dialect
from mintlang.migrate import engine
from mintlang.migrate.mintmt import addressing, blocks, characters, comments, events, names
from mintlang.migrate.mintmt.apply import apply
from mintlang.migrate.mintmt.source import Action, Source
from mintlang.migrate.model import MigrationResult

# One module per kind of rewrite, each with its ID, SUMMARY and find(source); the order is the report's.
REWRITES: tuple[ModuleType, ...] = (comments, characters, addressing, blocks, events, names)


def to_mintmt(source: str, *, config: str | None = None) -> MigrationResult:
    """Rewrite a Mint v4 program (and its configuration file, whose result is ``.configuration``) in
    MintMT's syntax where the notes show it, flagging what they do not. An application that already
    shows a form only MintMT has (``mintlang.detection``) comes back as it was, ``already_mintmt`` set."""
    texts = [text for text in (source, config) if text is not None]
    if any(detect_dialect(text) is Dialect.MINTMT for text in texts):
        return _result(engine.untouched(source), config and engine.untouched(config), already=True)
    configuration = Source(config) if config is not None else None
    program = Source(source, configuration.macros if configuration is not None else frozenset())
    migrated_configuration = apply(configuration, list(_actions(configuration))) if configuration else None
    return _result(apply(program, list(_actions(program))), migrated_configuration, already=False)


def _actions(source: Source) -> Iterator[Action]:
    for rewrite in REWRITES:
        yield from rewrite.find(source)


def _result(program: engine.FileOutcome, configuration: engine.FileOutcome | None, *, already: bool) -> MigrationResult:
    result = _of(program, already)
    return replace(result, configuration=_of(configuration, already)) if configuration is not None else result


def _of(outcome: engine.FileOutcome, already: bool) -> MigrationResult:
    return MigrationResult(
        outcome.source, outcome.text, outcome.changes, outcome.manual, outcome.counts, already_mintmt=already
    )
