"""mint-migrate: the Mint v3 → v4 migrator (``mintlang.migrate``).

A rule engine over the shared parser: every rule is a small named unit (see
``rules()`` or ``mint-migrate --list-rules``) that yields span edits or manual
items; the engine applies them to the original text, so everything a rule does
not touch survives byte for byte::

    from mintlang.migrate import migrate, rules_at
    result = migrate(v3_source, config=v3_config, controller="nextmove-pci")
    result.text, result.changes, result.manual, result.rule_counts, result.edits()
    result.already_v4  # recognised as Mint v4 and left as it was
    shows_v4({Unit.PROGRAM: source}, "nextmove-pci")  # a form only v4 has: not a v3 file
    rules_at(v3_source, offset)  # single-rule quick fixes at a position

A bug a rule meets raises ``MigrationFailed`` naming the rule; the CLI reports it
for that application only and goes on with the others. ``mintlang.migrate.mintmt``
is the Mint v4 → MintMT migration (``mint-migrate --to mintmt``), with the same
result and report.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from mintlang.lazy import import_when_used

if TYPE_CHECKING:
    from mintlang.migrate.api import DEFAULT_CONTROLLER, UnknownRule, migrate, rules, rules_at, select
    from mintlang.migrate.model import (
        Change,
        ManualItem,
        MigrationFailed,
        MigrationResult,
        Phase,
        RuleClass,
        RuleInfo,
    )
    from mintlang.migrate.recognise import shows_v4

__all__ = [
    "DEFAULT_CONTROLLER",
    "Change",
    "ManualItem",
    "MigrationFailed",
    "MigrationResult",
    "Phase",
    "RuleClass",
    "RuleInfo",
    "UnknownRule",
    "migrate",
    "rules",
    "rules_at",
    "select",
    "shows_v4",
]


# Imported when first used: ``mint-migrate --help`` imports ``mintlang.migrate.cli``, and with it this
# package, without the rules and the parser.
import_when_used(
    __name__,
    {
        **dict.fromkeys(
            ["DEFAULT_CONTROLLER", "UnknownRule", "migrate", "rules", "rules_at", "select"], "mintlang.migrate.api"
        ),
        **dict.fromkeys(
            ["Change", "ManualItem", "MigrationFailed", "MigrationResult", "Phase", "RuleClass", "RuleInfo"],
            "mintlang.migrate.model",
        ),
        "shows_v4": "mintlang.migrate.recognise",
    },
)
