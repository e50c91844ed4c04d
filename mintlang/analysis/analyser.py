"""Runs the parser's, the block matcher's and every rule's findings together."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from mintlang.allocation import without_collector
from mintlang.analysis.findings import Finding
from mintlang.analysis.rules import RULES
from mintlang.analysis.traversal import gather
from mintlang.diagnostics import Diagnostic
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.symbols import Unit


@dataclass(frozen=True, slots=True)
class Analysis:
    model: SemanticModel
    program: tuple[Diagnostic, ...]
    configuration: tuple[Diagnostic, ...]


def _selected(code: str, select: Iterable[str] | None, ignore: Iterable[str]) -> bool:
    """``--select``/``--ignore`` match a code or a prefix of it (E2, W1, E3001)."""
    if any(code.startswith(prefix) for prefix in ignore):
        return False
    return select is None or any(code.startswith(prefix) for prefix in select)


@without_collector
def analyse(model: SemanticModel, *, select: Iterable[str] | None = None, ignore: Iterable[str] = ()) -> Analysis:
    """All diagnostics of an application, per file, sorted by position."""
    select = tuple(select) if select is not None else None
    ignore = tuple(ignore)
    findings: list[Finding] = []
    for unit, document in model.documents():
        findings.extend(Finding(unit, diagnostic) for diagnostic in document.diagnostics)
        findings.extend(Finding(unit, diagnostic) for diagnostic in model.structures[unit].diagnostics)
    facts = gather(model)
    for rule in RULES:
        if model.program.dialect in rule.dialects:
            findings.extend(rule.check(facts))
    per_unit: dict[Unit, list[Diagnostic]] = {Unit.PROGRAM: [], Unit.CONFIGURATION: []}
    seen: set[tuple[Unit, str, int, int]] = set()
    for finding in findings:
        diagnostic = finding.diagnostic
        key = (finding.unit, diagnostic.code, diagnostic.span.start, diagnostic.span.end)
        if key in seen or not _selected(diagnostic.code, select, ignore):
            continue
        seen.add(key)
        per_unit[finding.unit].append(diagnostic)
    for diagnostics in per_unit.values():
        diagnostics.sort(key=lambda d: (d.span.start, d.span.end, d.code))
    return Analysis(model, tuple(per_unit[Unit.PROGRAM]), tuple(per_unit[Unit.CONFIGURATION]))
