"""Runs the parser's, the block matcher's and every rule's findings together.

The line rules run once per line syntax, unit, controller and dialect: after an
edit only the changed lines are checked again, and the whole-application rules
(declarations, flow, limits, unused names ...) run over the index the model
already holds. After an edit that changed no line's meaning (the model was
carried over, ``mintlang.semantic.carry``), what they found is carried over too,
moved by the edit; the length of the program, which every edit changes, is
checked again against the memory (``rules.memory``).
"""

from __future__ import annotations

from array import array
from collections.abc import Callable, Hashable, Iterable, Iterator, Mapping, Sequence
from functools import cache, partial
from itertools import chain, repeat
from operator import attrgetter

from mintlang.allocation import without_collector
from mintlang.analysis.rules import RULES, Rule, memory
from mintlang.analysis.suppression import Directive, directives, suppress
from mintlang.analysis.traversal import Facts, LineScope, LineShape, gather, line_shape
from mintlang.caching import LINES_KEPT, RecentCache
from mintlang.codes import DEFAULT_SELECT
from mintlang.controllers import ControllerProfile
from mintlang.diagnostics import Diagnostic
from mintlang.dialect import Dialect
from mintlang.keyworddb.model import Controller
from mintlang.records import record
from mintlang.semantic.index import LineFacts, line_facts
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.symbols import Unit
from mintlang.syntax import nodes as n
from mintlang.syntax.change import Change
from mintlang.syntax.moved import bisect_left
from mintlang.syntax.packed import PlacedDiagnostics
from mintlang.syntax.parser import Document


@record
class Found:
    """What the rules found, per file, before selection and suppression: kept so that the next
    version's check carries over what its edit did not touch."""

    in_lines: Mapping[Unit, tuple[Diagnostic, ...]]  # by the line rules: a logical or physical line's each
    whole: Mapping[Unit, tuple[tuple[Rule, Diagnostic], ...]]  # by the whole-application rules
    arrays: memory.ArrayDemand
    directives: Mapping[Unit, tuple[Directive, ...]]  # the suppression comments, applied after selection


@record
class Analysis:
    model: SemanticModel
    program: Sequence[Diagnostic]  # ``PlacedDiagnostics``: each made when read
    configuration: Sequence[Diagnostic]
    found: Found


def _selected(code: str, *, select: tuple[str, ...] | None, ignore: tuple[str, ...]) -> bool:
    return code_selected(code, select, ignore)


def code_selected(code: str, select: Iterable[str] | None, ignore: Iterable[str]) -> bool:
    """``--select``/``--ignore`` match a code or a prefix of it (E2, W1, E3001)."""
    if any(code.startswith(prefix) for prefix in ignore):
        return False
    return any(code.startswith(prefix) for prefix in (DEFAULT_SELECT if select is None else select))


_Context = tuple[Unit, Controller, Dialect]  # where a line is checked
# Per context, by what the line was parsed from (no key tuple per line). The contexts used last are kept.
_line_findings: dict[_Context, RecentCache[Hashable, tuple[Diagnostic, ...]]] = {}
_CONTEXTS_KEPT = 4  # the two files of an application, on one or two controllers


def clear_cache() -> None:
    """Empty the per-line findings caches: in an ``apart`` block, only the block's own lines (a migration
    drops what its Mint v3 checks found once no check of that text is to come)."""
    for findings in _line_findings.values():
        findings.clear()


def _findings_cache(context: _Context) -> RecentCache[Hashable, tuple[Diagnostic, ...]]:
    cache = _line_findings.pop(context, None)
    if cache is None:
        cache = RecentCache(LINES_KEPT)
        if len(_line_findings) >= _CONTEXTS_KEPT:
            del _line_findings[next(iter(_line_findings))]  # the one used longest ago
    _line_findings[context] = cache  # last in order: used most recently
    return cache


@cache
def _rules_for(dialect: Dialect) -> tuple[tuple[Rule, ...], tuple[Rule, ...], tuple[Rule, ...]]:
    """The rules that read one line, those that read the whole application, and those that read the text."""
    rules = [rule for rule in RULES if dialect in rule.dialects]
    return (
        tuple(rule for rule in rules if rule.each_line),
        tuple(rule for rule in rules if rule.check),
        tuple(rule for rule in rules if rule.each_text_line),
    )


@cache
def _line_rules_for(dialect: Dialect, shape: LineShape) -> tuple[Rule, ...]:
    """The line rules of ``dialect`` that read something a line of ``shape`` has: most lines
    have none of what most rules look for, and a rule's pass over such a line finds nothing."""
    return tuple(rule for rule in _rules_for(dialect)[0] if rule.looks_at is None or rule.looks_at.found_in(shape))


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
        for rule in _line_rules_for(dialect, line_shape(line.syntax, facts))
        for finding in rule.each_line(scope)  # type: ignore[misc]
    )
    cache.put(line.content, found)
    return found


def _in_position_order(diagnostics: Iterable[Diagnostic]) -> list[Diagnostic]:
    """The diagnostics by span, then by code; stable, so equals keep the order they were found in."""
    ordered = list(diagnostics)
    ordered.sort(key=_CODE)  # in place: one list, where sorted(sorted(...)) held three on a file of errors
    ordered.sort(key=_SPAN)
    return ordered


_CODE = attrgetter("code")
_SPAN = attrgetter("span")


def _same_place(diagnostic: Diagnostic, origin: int, other: Diagnostic, other_origin: int) -> bool:
    span, other_span = diagnostic.span, other.span
    return span.start + origin == other_span.start + other_origin and span.end + origin == other_span.end + other_origin


def _with_origins(diagnostics: Sequence[Diagnostic]) -> Iterator[tuple[Diagnostic, int]]:
    """Each diagnostic as found, with the offset that places it in its file (none: it is placed)."""
    if isinstance(diagnostics, PlacedDiagnostics):
        return diagnostics.pairs()
    return zip(diagnostics, repeat(0))


def _first_of_each(found: Iterable[tuple[Diagnostic, int]]) -> PlacedDiagnostics:
    """The diagnostics in position order (by span, then by code; stable, so equals keep the order they
    were found in), the first found of each code at each span only.

    They stay as found, each with its offset, and are placed when read: on a file of broken
    lines, shifted copies of them all were the largest part of a check's memory. Their order
    comes from stable sorts of their indices on one number or code each, rather than one sort
    on a tuple made for each; equal ones end up neighbours, so no set of every place is needed.
    """
    diagnostics: list[Diagnostic] = []
    origins = array("q")
    for diagnostic, origin in found:
        diagnostics.append(diagnostic)
        origins.append(origin)
    order = sorted(range(len(diagnostics)), key=lambda index: diagnostics[index].code)
    order.sort(key=lambda index: diagnostics[index].span.end + origins[index])
    order.sort(key=lambda index: diagnostics[index].span.start + origins[index])
    kept: list[Diagnostic] = []
    kept_origins = array("q")
    last: Diagnostic | None = None
    last_origin = 0
    for index in order:
        diagnostic, origin = diagnostics[index], origins[index]
        if last is None or diagnostic.code != last.code or not _same_place(diagnostic, origin, last, last_origin):
            kept.append(diagnostic)
            kept_origins.append(origin)
            last, last_origin = diagnostic, origin
    return PlacedDiagnostics(tuple(kept), kept_origins)


@without_collector
def analyse(
    model: SemanticModel,
    *,
    select: Iterable[str] | None = None,
    ignore: Iterable[str] = (),
    config_ignore: Iterable[str] | None = None,
    previous: Analysis | None = None,
    suppressions: bool = True,
) -> Analysis:
    """All diagnostics of an application, per file, sorted by position.

    ``config_ignore`` is what the configuration file ignores, when a ``per-file-ignores`` glob
    matches it and not the program, or the other way round; None: ``ignore``.

    ``previous`` is the analysis of the version ``model`` was carried over from
    (``mintlang.semantic.carry``): what its edit did not touch is carried over too.

    ``suppressions`` False reports what the suppression comments silence: a comment is the checker's, and
    the controller's compiler stops on an error whatever it says.
    """
    found = _carried(model, previous) if previous is not None else None
    if found is None:
        found = _find(model)
    select = tuple(select) if select is not None else None
    ignores = {Unit.PROGRAM: tuple(ignore)}
    ignores[Unit.CONFIGURATION] = ignores[Unit.PROGRAM] if config_ignore is None else tuple(config_ignore)
    per_unit: dict[Unit, Sequence[Diagnostic]] = {Unit.CONFIGURATION: ()}
    for unit, document in model.documents():
        selected = partial(_selected, select=select, ignore=ignores[unit])
        placed = chain(
            document.lexer_issues,
            model.structures[unit].diagnostics,
            found.in_lines[unit],
            (diagnostic for _, diagnostic in found.whole[unit]),
            (finding.diagnostic for finding in memory.findings(model, found.arrays) if finding.unit is unit),
        )
        everything = chain(_with_origins(document.parse_issues), zip(placed, repeat(0)))
        distinct = _first_of_each(pair for pair in everything if selected(pair[0].code))
        kept = suppress(distinct, found.directives[unit], selected) if suppressions else distinct
        per_unit[unit] = distinct if kept is distinct else tuple(_in_position_order(kept))
    return Analysis(model, per_unit[Unit.PROGRAM], per_unit[Unit.CONFIGURATION], found)


def _find(model: SemanticModel) -> Found:
    """What every rule finds in the whole application."""
    in_lines: dict[Unit, tuple[Diagnostic, ...]] = {Unit.CONFIGURATION: ()}
    comments: dict[Unit, tuple[Directive, ...]] = {Unit.CONFIGURATION: ()}
    for unit, document in model.documents():
        in_lines[unit] = (
            *_in_logical_lines(model, unit, model.lines.of(unit)),
            *_in_text_lines(model, document, range(len(document.physical))),
        )
        comments[unit] = directives(document)
    return Found(in_lines, _whole(model), memory.demand(model.symbols), comments)


def _whole(
    model: SemanticModel, kept: Callable[[Rule], list[tuple[Unit, Diagnostic]] | None] = lambda rule: None
) -> dict[Unit, tuple[tuple[Rule, Diagnostic], ...]]:
    """What the whole-application rules find, per file; each rule's ``kept`` findings where it has them,
    in the rules' order (of equal findings, the first is the one kept)."""
    whole: dict[Unit, list[tuple[Rule, Diagnostic]]] = {Unit.PROGRAM: [], Unit.CONFIGURATION: []}
    facts: Facts | None = None  # gathered for the first rule that runs
    for rule in _rules_for(model.program.dialect)[1]:
        found = kept(rule)
        if found is None:
            facts = facts or gather(model)
            found = [(finding.unit, finding.diagnostic) for finding in rule.check(facts)]  # type: ignore[misc]
        for unit, diagnostic in found:
            whole[unit].append((rule, diagnostic))
    return {unit: tuple(found) for unit, found in whole.items()}


def _in_logical_lines(
    model: SemanticModel, unit: Unit, lines: Iterable[tuple[n.PlacedLine, LineFacts]]
) -> Iterator[Diagnostic]:
    """What the line rules find in ``lines`` of ``unit``'s file, at offsets into it."""
    dialect, controller = model.program.dialect, model.controller
    cache = _findings_cache((unit, controller.controller, dialect))
    for line, facts in lines:
        for diagnostic in _findings_of_line(cache, unit, line, facts, controller=controller, dialect=dialect):
            yield diagnostic.shifted(line.origin)


def _in_text_lines(model: SemanticModel, document: Document, indices: range) -> Iterator[Diagnostic]:
    """What the rules that read the text as written find in physical lines ``indices`` of ``document``."""
    for rule in _rules_for(model.program.dialect)[2]:
        yield from rule.each_text_line(document.physical, indices, model.controller, model.program.dialect)  # type: ignore[misc]


def _carried(model: SemanticModel, previous: Analysis) -> Found | None:
    """What ``previous`` found, moved over the edit ``model`` was carried over by, with the lines the
    edit touched checked again, and each whole-application rule run again where what it reads of
    them changed, or where a finding of it lies in them."""
    carried = model.carried
    if carried is None:
        return None
    change = carried.change
    in_lines = dict(previous.found.in_lines)
    in_lines[Unit.PROGRAM] = change.spliced(previous.found.in_lines[Unit.PROGRAM], _in_window(model, change))
    comments = dict(previous.found.directives)
    comments[Unit.PROGRAM] = change.spliced(
        previous.found.directives[Unit.PROGRAM], directives(model.program, change.start, change.new_end)
    )
    same = carried.same_facts

    def kept(rule: Rule) -> list[tuple[Unit, Diagnostic]] | None:
        if not (same or (rule.reads is not None and carried.same_for(rule.reads))):
            return None
        return _carried_findings(previous.found, rule, change)

    arrays = _carried_arrays(previous.found.arrays, change) if same else None
    arrays = arrays if arrays is not None else memory.demand(model.symbols)
    return Found(in_lines, _whole(model, kept), arrays, comments)


def _carried_findings(before: Found, rule: Rule, change: Change) -> list[tuple[Unit, Diagnostic]] | None:
    """What ``rule`` found before, moved; None where one of its findings lies in the edit's window."""
    found: list[tuple[Unit, Diagnostic]] = [
        (Unit.CONFIGURATION, diagnostic) for of, diagnostic in before.whole[Unit.CONFIGURATION] if of is rule
    ]
    for of, diagnostic in before.whole[Unit.PROGRAM]:
        if of is rule:
            moved = change.diagnostic(diagnostic)
            if moved is None:
                return None
            found.append((Unit.PROGRAM, moved))
    return found


def _carried_arrays(before: memory.ArrayDemand, change: Change) -> memory.ArrayDemand | None:
    largest = before.largest
    if largest is None or largest[0] is not Unit.PROGRAM:
        return before
    span = change.span(largest[1])
    return memory.ArrayDemand(before.bytes, (Unit.PROGRAM, span)) if span is not None else None


def _in_window(model: SemanticModel, change: Change) -> list[Diagnostic]:
    """What the line rules find in the lines of the program that ``change`` touched."""
    program = model.program
    window = program.placed[change.first_line : change.first_line + change.new_lines]
    found = list(_in_logical_lines(model, Unit.PROGRAM, ((line, line_facts(Unit.PROGRAM, line)) for line in window)))
    offsets = program.physical.offsets
    found.extend(
        _in_text_lines(model, program, range(bisect_left(offsets, change.start), bisect_left(offsets, change.new_end)))
    )
    return found
