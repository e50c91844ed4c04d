"""The migrator as a library: whole files for the CLI, single rules for the language server."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import replace
from functools import cache

from mintlang.detection import detect_dialect
from mintlang.diagnostics import Edit, Span
from mintlang.dialect import Dialect
from mintlang.keyworddb.model import Controller
from mintlang.migrate import engine
from mintlang.migrate.context import Context
from mintlang.migrate.model import MigrationResult, RuleInfo
from mintlang.migrate.recognise import Evidence, marked, may_show_v4_beyond_doubt, v4_evidence, valid_v4
from mintlang.migrate.rules import RULES, Replace, Rule
from mintlang.records import record
from mintlang.semantic.units import Unit
from mintlang.syntax.tokens import BYTE_ORDER_MARK, end_of_file_mark

DEFAULT_CONTROLLER = Controller.NEXTMOVE_PCI


class UnknownRule(ValueError):
    """``only``/``skip``/``opt_in`` named a rule id that does not exist, or ``opt_in`` one that
    is not optional (asking for it would do nothing, which a typo deserves to hear)."""


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
    if extra & default:
        optional = ", ".join(rule.id for rule in RULES if rule.optional)
        raise UnknownRule(
            f"not an optional rule: {', '.join(sorted(extra & default))} runs anyway (the optional ones: {optional})"
        )
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
    ``only``/``skip``/``opt_in`` choose the rules as ``select`` does. An application already
    in Mint v4 comes back as it was, ``already_v4`` set (see ``recognise``), and one that shows a
    form only MintMT has (``mintlang.detection``) too, ``already_mintmt`` set: read as v3, each of
    its ``'`` comments would be flagged. Raises ``MigrationFailed`` when a rule fails."""
    texts = {Unit.PROGRAM: source}
    if config is not None:
        texts = {Unit.CONFIGURATION: config, **texts}
    marks = {unit: _marks(text) for unit, text in texts.items()}
    texts = {unit: text[len(marks[unit].start) : len(text) - len(marks[unit].end)] for unit, text in texts.items()}
    if any(detect_dialect(text) is Dialect.MINTMT for text in texts.values()):
        kept = {unit: engine.untouched(text) for unit, text in texts.items()}
        return _application({unit: _result(outcome, marks[unit], mintmt=True) for unit, outcome in kept.items()})
    target = str(Controller(controller))
    chosen = select(only, skip, opt_in)
    outcomes = engine.run(texts, chosen, target)
    v4 = _already_v4(texts, target, outcomes, chosen)
    if v4:
        outcomes = {unit: engine.untouched(text) for unit, text in texts.items()}
    return _application({unit: _result(outcome, marks[unit], v4=v4) for unit, outcome in outcomes.items()})


@record
class _Marks:
    """What a file holds around its text that the rules do not see: a byte-order mark, and Ctrl-Z at the end
    (``end_of_file_mark``), which stays last, byte for byte, and is no "unexpected character" to flag."""

    start: str
    end: str


def _marks(text: str) -> _Marks:
    """The marks around ``text``. The rules migrate the text inside them: a prologue inserted at offset 0
    would otherwise push a byte-order mark into the middle of the file."""
    start = BYTE_ORDER_MARK if text.startswith(BYTE_ORDER_MARK) else ""
    body = text.removeprefix(start)
    return _Marks(start, end_of_file_mark(body))


def _application(results: Mapping[Unit, MigrationResult]) -> MigrationResult:
    """The program's result, with the configuration file's as its ``.configuration``."""
    if Unit.CONFIGURATION in results:
        return replace(results[Unit.PROGRAM], configuration=results[Unit.CONFIGURATION])
    return results[Unit.PROGRAM]


def _already_v4(
    texts: Mapping[Unit, str], target: str, outcomes: Mapping[Unit, engine.FileOutcome], chosen: tuple[Rule, ...]
) -> bool:
    """Whether the application is Mint v4 already (see ``recognise``): the rules rewrite nothing in it
    and it shows a v4 form; or it shows one beyond doubt, or it holds the migrator's markers and the rules
    would only rename its v4 keywords as variables, and v4 finds no error in it."""
    rewrite_free, migrated = _rewrite_free(outcomes), marked(texts)
    if not (rewrite_free or migrated) and not may_show_v4_beyond_doubt(texts, target):
        return False  # most v3 programs: no v4 reading needed
    evidence = v4_evidence(texts, target)

    @cache  # a second migration, when some rules only were asked for: run once at most
    def all_rules() -> Mapping[Unit, engine.FileOutcome]:  # whether a file is v4 does not depend on the rules asked for
        return outcomes if chosen == select() else engine.run(texts, select(), target)

    if rewrite_free and evidence is not Evidence.NONE and _rewrite_free(all_rules()):
        return True
    if migrated and _renames_only(all_rules()):
        return valid_v4(texts, target)
    return evidence is Evidence.BEYOND_DOUBT and valid_v4(texts, target)


def _rewrite_free(outcomes: Mapping[Unit, engine.FileOutcome]) -> bool:
    """Whether the rules rewrote nothing (markers and notes are no rewrites)."""
    return not any(outcome.changes for outcome in outcomes.values())


_RENAMING = frozenset({"M-IDENT", "M-DIM"})  # a v3 variable named as a v4 keyword renamed, and declared


def _renames_only(outcomes: Mapping[Unit, engine.FileOutcome]) -> bool:
    """Whether the rules' only rewrites rename names as v3 variables (``kprop`` to ``kprop_u``): what they make of
    the migrator's own output, whose v4 keywords they read as v3 variables. Any other rewrite is v3 a run of some
    rules only (``--skip M-TRIG``) left."""
    return all(change.rule in _RENAMING for outcome in outcomes.values() for change in outcome.changes)


def _result(outcome: engine.FileOutcome, marks: _Marks, *, v4: bool = False, mintmt: bool = False) -> MigrationResult:
    """The outcome with the marks the rules did not see put back where they were."""
    shift = len(marks.start)
    changes = tuple(
        replace(change, span=Span(change.span.start + shift, change.span.end + shift)) for change in outcome.changes
    )
    return MigrationResult(
        marks.start + outcome.source + marks.end,
        marks.start + outcome.text + marks.end,
        changes,
        outcome.manual,
        outcome.counts,
        outcome.errors,
        already_v4=v4,
        already_mintmt=mintmt,
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
