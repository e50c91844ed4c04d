"""The migrator as a library: whole files for the CLI, single rules for the language server."""

from __future__ import annotations

from collections.abc import Iterable

from mintlang.diagnostics import Edit
from mintlang.keyworddb.model import Controller
from mintlang.migrate import engine
from mintlang.migrate.context import Context
from mintlang.migrate.model import MigrationResult, RuleInfo
from mintlang.migrate.rules import RULES, Replace, Rule
from mintlang.semantic.units import Unit

DEFAULT_CONTROLLER = Controller.NEXTMOVE_PCI


class UnknownRule(ValueError):
    """``only``/``skip`` named a rule id that does not exist."""


def rules() -> tuple[RuleInfo, ...]:
    """Every rule in the order the engine runs them (what ``--list-rules`` prints)."""
    return tuple(rule.info() for rule in RULES)


def select(only: Iterable[str] | None = None, skip: Iterable[str] = (), opt_in: Iterable[str] = ()) -> tuple[Rule, ...]:
    """The rules to run: ``only`` those ids (default: every rule that is not optional, plus the
    optional ones named in ``opt_in``), minus ``skip``. Naming an optional rule in ``only`` is
    asking for it too."""
    known = {rule.id for rule in RULES}
    extra = {rule.upper() for rule in opt_in}
    default = {rule.id for rule in RULES if not rule.optional}
    wanted = {rule.upper() for rule in only} if only is not None else default | extra
    skipped = {rule.upper() for rule in skip}
    unknown = sorted((wanted | skipped | extra) - known)
    if unknown:
        raise UnknownRule(f"unknown rule: {', '.join(unknown)} (see --list-rules)")
    return tuple(rule for rule in RULES if rule.id in wanted - skipped)


def migrate(
    source: str,
    *,
    config: str | None = None,
    controller: Controller | str = DEFAULT_CONTROLLER,
    only: Iterable[str] | None = None,
    skip: Iterable[str] = (),
    opt_in: Iterable[str] = (),
) -> MigrationResult:
    """Migrate a v3 program (and its configuration file, whose result is ``.configuration``);
    ``only``/``skip``/``opt_in`` choose the rules as ``select`` does."""
    texts = {Unit.PROGRAM: source}
    if config is not None:
        texts = {Unit.CONFIGURATION: config, **texts}
    outcomes = engine.run(texts, select(only, skip, opt_in), str(Controller(controller)))
    results = {unit: _result(outcome) for unit, outcome in outcomes.items()}
    program = results[Unit.PROGRAM]
    if Unit.CONFIGURATION in results:
        return MigrationResult(
            program.source,
            program.text,
            program.changes,
            program.manual,
            program.rule_counts,
            program.errors,
            results[Unit.CONFIGURATION],
        )
    return program


def _result(outcome: engine.FileOutcome) -> MigrationResult:
    return MigrationResult(
        outcome.source, outcome.text, outcome.changes, outcome.manual, outcome.counts, outcome.errors
    )


def rules_at(
    source: str, offset: int, *, config: str | None = None, controller: Controller | str = DEFAULT_CONTROLLER
) -> tuple[tuple[RuleInfo, tuple[Edit, ...]], ...]:
    """Quick fixes at ``offset`` of a v3 program: each rule with a rewrite touching that offset,
    and its edits on ``source`` alone (one rule, one pass: what an editor offers as
    "replace HMSPEED with HOMESPEED")."""
    texts = {Unit.PROGRAM: source}
    if config is not None:
        texts[Unit.CONFIGURATION] = config
    context = Context.build(texts, str(Controller(controller)))
    fixes = []
    for rule in RULES:
        edits = tuple(
            Edit(action.span, action.text)
            for action in rule.apply(context)
            if isinstance(action, Replace) and action.unit is Unit.PROGRAM
        )
        if any(edit.span.start <= offset <= edit.span.end for edit in edits):
            local = tuple(edit for edit in edits if edit.span.start <= offset <= edit.span.end)
            fixes.append((rule.info(), local))
    return tuple(fixes)
