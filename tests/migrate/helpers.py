"""Shared helpers: run one rule on a snippet and look at the text or the manual items."""

from __future__ import annotations

from mintlang.migrate import MigrationResult, migrate


def one_rule(rule: str, source: str, *, controller: str = "nextmove-pci", config: str | None = None) -> MigrationResult:
    return migrate(source, only=[rule], controller=controller, config=config)


def rewritten(rule: str, source: str, **options: str) -> str:
    return one_rule(rule, source, **options).text


def flagged(rule: str, source: str, **options: str) -> list[str]:
    """The reasons of the manual items ``rule`` left (the text must otherwise be unchanged)."""
    result = one_rule(rule, source, **options)
    marker_free = "".join(line for line in result.text.splitlines(keepends=True) if "REM MIGRATE:" not in line)
    assert marker_free == source, "a refused rewrite must leave the original as it was"
    return [item.reason for item in result.manual if item.rule == rule]
