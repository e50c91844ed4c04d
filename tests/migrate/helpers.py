"""Shared helpers: run one rule on a snippet and look at the text or the manual items."""

from __future__ import annotations

import mintlang
from mintlang.diagnostics import LineIndex, Severity
from mintlang.keyworddb import database
from mintlang.migrate import MigrationResult, migrate


def one_rule(rule: str, source: str, *, controller: str = "nextmove-pci", config: str | None = None) -> MigrationResult:
    return migrate(source, only=[rule], controller=controller, config=config)


def rewritten(rule: str, source: str, **options: str) -> str:
    return one_rule(rule, source, **options).text


def migrated_twice(rule: str, source: str) -> tuple[object, ...]:
    """What ``rule`` alone makes of ``source`` and then of its own output: each text and its manual items; a rule
    that settles gives ``(text, (), text, ())``."""
    migrated = migrate(source, only=[rule])
    again = migrate(migrated.text, only=[rule])
    return (migrated.text, migrated.manual, again.text, again.manual)


def flagged(rule: str, source: str, **options: str) -> list[str]:
    """The reasons of the manual items ``rule`` left (the text must otherwise be unchanged)."""
    result = one_rule(rule, source, **options)
    marker_free = "".join(line for line in result.text.splitlines(keepends=True) if "REM MIGRATE:" not in line)
    assert marker_free == source, "a refused rewrite must leave the original as it was"
    return [item.reason for item in result.manual if item.rule == rule]


def unflagged_errors(result: MigrationResult, diagnostics: tuple[mintlang.Diagnostic, ...]) -> list[str]:
    """The error diagnostics of the migrated text that sit on no line a manual item flags."""
    flagged_lines = {item.line for item in result.manual}
    index = LineIndex(result.text)
    return [
        f"{index.position(d.span.start).line}: {d.code} {d.message}"
        for d in diagnostics
        if d.severity is Severity.ERROR and index.position(d.span.start).line not in flagged_lines
    ]


def errors_left_unflagged(result: MigrationResult, controller: str) -> list[str]:
    """``unflagged_errors`` of ``mint check`` on the program and its configuration file, if any."""
    config = result.configuration.text if result.configuration is not None else None
    analysis = mintlang.check_application(result.text, dialect="v4", controller=controller, config=config)
    left = unflagged_errors(result, analysis.program)
    if result.configuration is not None:
        left += [f"configuration {error}" for error in unflagged_errors(result.configuration, analysis.configuration)]
    return left


def every_word() -> list[str]:
    """Every keyword of both dialects and every abbreviation, each once, sorted: the migrator's keyword sweeps."""
    db = database()
    words = set(db.v3_keywords) | set(db.keywords)
    for keyword in (*db.v3_keywords.values(), *db.keywords.values()):
        words.update(keyword.abbreviations)
    return sorted(words)
