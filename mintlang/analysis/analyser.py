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
from mintlang.analysis.rules import RULES, Rule
from mintlang.analysis.suppression import suppress
from mintlang.analysis.traversal import LineScope, gather
from mintlang.caching import LINES_KEPT, RecentCache
from mintlang.codes import DEFAULT_SELECT
from mintlang.controllers import ControllerProfile
from mintlang.diagnostics import Diagnostic, Span
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


def _by_position(diagnostic: Diagnostic) -> tuple[Span, str]:
    return diagnostic.span, diagnostic.code


def _first_of_each(diagnostics: Iterable[Diagnostic]) -> list[Diagnostic]:
    """The diagnostics in position order, the first found of each code at each span only.

    Sorted first (a stable sort keeps the order found among equals), so equal ones are
    neighbours: no set of every position, which took more memory than the diagnostics
    themselves on a file of broken lines.
    """
    distinct: list[Diagnostic] = []
    last: tuple[Span, str] | None = None
    for diagnostic in sorted(diagnostics, key=_by_position):
        place = (diagnostic.span, diagnostic.code)
        if place != last:
            distinct.append(diagnostic)
            last = place
    return distinct


@without_collector
def analyse(model: SemanticModel, *, select: Iterable[str] | None = None, ignore: Iterable[str] = ()) -> Analysis:
    """All diagnostics of an application, per file, sorted by position."""
    select = tuple(select) if select is not None else None
    ignore = tuple(ignore)
    found: dict[Unit, list[Diagnostic]] = {Unit.PROGRAM: [], Unit.CONFIGURATION: []}  # per file, as found
    for unit, document in model.documents():
        found[unit].extend(document.diagnostics)
        found[unit].extend(model.structures[unit].diagnostics)
    dialect, controller = model.program.dialect, model.controller
    caches = {unit: _findings_cache((unit, controller.controller, dialect)) for unit in Unit}
    for unit, line, facts in model.lines:
        in_line = _findings_of_line(caches[unit], unit, line, facts, controller=controller, dialect=dialect)
        if in_line:
            found[unit].extend(diagnostic.shifted(line.origin) for diagnostic in in_line)
    facts = gather(model)
    for rule in _rules_for(dialect)[1]:
        for finding in rule.check(facts):  # type: ignore[misc]
            found[finding.unit].append(finding.diagnostic)

    def selected(code: str) -> bool:
        return _selected(code, select, ignore)

    per_unit: dict[Unit, list[Diagnostic]] = {}
    for unit, document in model.documents():
        distinct = _first_of_each(diagnostic for diagnostic in found[unit] if selected(diagnostic.code))
        per_unit[unit] = sorted(suppress(distinct, document, selected), key=_by_position)
    per_unit.setdefault(Unit.CONFIGURATION, [])
    return Analysis(model, tuple(per_unit[Unit.PROGRAM]), tuple(per_unit[Unit.CONFIGURATION]))
