"""Runs the parser's, the block matcher's and every rule's findings together.

The line rules run once per line syntax, unit, controller and dialect: after an
edit only the changed lines are checked again, and the whole-application rules
(declarations, flow, limits, unused names ...) run over the index the model
already holds.
"""

from __future__ import annotations

from collections.abc import Hashable, Iterable
from dataclasses import dataclass
from functools import cache

from mintlang.allocation import without_collector
from mintlang.analysis.findings import Finding
from mintlang.analysis.rules import RULES, Rule
from mintlang.analysis.suppression import suppress
from mintlang.analysis.traversal import LineScope, gather
from mintlang.caching import LINES_KEPT, RecentCache
from mintlang.codes import DEFAULT_SELECT
from mintlang.controllers import ControllerProfile
from mintlang.diagnostics import Diagnostic
from mintlang.dialect import Dialect
from mintlang.keyworddb.model import Controller
from mintlang.semantic.index import LineFacts
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.symbols import Unit
from mintlang.syntax import nodes as n


@dataclass(frozen=True, slots=True)
class Analysis:
    model: SemanticModel
    program: tuple[Diagnostic, ...]
    configuration: tuple[Diagnostic, ...]


def _selected(code: str, select: Iterable[str] | None, ignore: Iterable[str]) -> bool:
    """``--select``/``--ignore`` match a code or a prefix of it (E2, W1, E3001)."""
    if any(code.startswith(prefix) for prefix in ignore):
        return False
    return any(code.startswith(prefix) for prefix in (DEFAULT_SELECT if select is None else select))


_Context = tuple[Unit, Controller, Dialect]  # where a line is checked
# Per context, by what the line was parsed from (no key tuple per line). The contexts used last are kept.
_line_findings: dict[_Context, RecentCache[Hashable, tuple[Diagnostic, ...]]] = {}
_CONTEXTS_KEPT = 4  # the two files of an application, on one or two controllers


def clear_cache() -> None:
    _line_findings.clear()


def _findings_cache(context: _Context) -> RecentCache[Hashable, tuple[Diagnostic, ...]]:
    cache = _line_findings.pop(context, None)
    if cache is None:
        cache = RecentCache(LINES_KEPT)
        if len(_line_findings) >= _CONTEXTS_KEPT:
            del _line_findings[next(iter(_line_findings))]  # the one used longest ago
    _line_findings[context] = cache  # last in order: used most recently
    return cache


@cache
def _rules_for(dialect: Dialect) -> tuple[tuple[Rule, ...], tuple[Rule, ...]]:
    """The rules that read one line, and those that read the whole application."""
    rules = [rule for rule in RULES if dialect in rule.dialects]
    return tuple(rule for rule in rules if rule.each_line), tuple(rule for rule in rules if rule.check)


def _findings_of_line(
    cache: RecentCache[Hashable, tuple[Diagnostic, ...]],
    unit: Unit,
    line: n.PlacedLine,
    facts: LineFacts,
    *,
    controller: ControllerProfile,
    dialect: Dialect,
) -> tuple[Diagnostic, ...]:
    """What the line rules find in one line, at its own offsets: computed once per line text."""
    cached = cache.get(line.content)
    if cached is not None:
        return cached
    scope = LineScope(unit, line.syntax, facts, controller, dialect)
    found = tuple(
        finding.diagnostic
        for rule in _rules_for(dialect)[0]
        for finding in rule.each_line(scope)  # type: ignore[misc]
    )
    cache.put(line.content, found)
    return found


@without_collector
def analyse(model: SemanticModel, *, select: Iterable[str] | None = None, ignore: Iterable[str] = ()) -> Analysis:
    """All diagnostics of an application, per file, sorted by position."""
    select = tuple(select) if select is not None else None
    ignore = tuple(ignore)
    findings: list[Finding] = []
    for unit, document in model.documents():
        findings.extend(Finding(unit, diagnostic) for diagnostic in document.diagnostics)
        findings.extend(Finding(unit, diagnostic) for diagnostic in model.structures[unit].diagnostics)
    dialect, controller = model.program.dialect, model.controller
    caches = {unit: _findings_cache((unit, controller.controller, dialect)) for unit in Unit}
    for unit, line, facts in model.lines:
        found = _findings_of_line(caches[unit], unit, line, facts, controller=controller, dialect=dialect)
        if found:
            findings.extend(Finding(unit, diagnostic.shifted(line.origin)) for diagnostic in found)
    facts = gather(model)
    for rule in _rules_for(dialect)[1]:
        findings.extend(rule.check(facts))  # type: ignore[misc]
    per_unit: dict[Unit, list[Diagnostic]] = {Unit.PROGRAM: [], Unit.CONFIGURATION: []}
    seen: set[tuple[Unit, str, int, int]] = set()
    for finding in findings:
        diagnostic = finding.diagnostic
        key = (finding.unit, diagnostic.code, diagnostic.span.start, diagnostic.span.end)
        if key in seen or not _selected(diagnostic.code, select, ignore):
            continue
        seen.add(key)
        per_unit[finding.unit].append(diagnostic)

    def selected(code: str) -> bool:
        return _selected(code, select, ignore)

    for unit, document in model.documents():
        per_unit[unit] = suppress(per_unit[unit], document, selected)
    for diagnostics in per_unit.values():
        diagnostics.sort(key=lambda d: (d.span.start, d.span.end, d.code))
    return Analysis(model, tuple(per_unit[Unit.PROGRAM]), tuple(per_unit[Unit.CONFIGURATION]))
