"""A line rule is skipped on a line that has none of what it says it reads (``Rule.looks_at``):
on every such line of every corpus and conformance program, in every dialect, it finds nothing.

The skip saves most of the line rules' time, and a rule that said less than it reads would
lose findings without a word; this holds every rule to what it says.
"""

from __future__ import annotations

import pytest

from mintlang.analysis.rules import RULES, Rule
from mintlang.analysis.traversal import LineParts, LineScope, line_shape
from mintlang.dialect import Dialect
from mintlang.semantic.model import build_model
from mintlang.syntax import nodes as n
from mintlang.syntax.parser import parse
from tests.conformance.cases import all_cases
from tests.corpus_files import CORPUS

# A finding of each rule on each kind of statement it reads, where the corpus may have none.
_EACH_KIND = """COMMS(1) =
PAUSE
DIM a(2.5)
INPUT b(1)
AXES
#FASTPOS
IF 1 THEN COMMS(300) = 1
PRINT 1 USING 20,2
x = 1 / 0
MOVER[0] = 1
DEFINE 1a = 2
ABS(1,2)
IF 1 THEN DINT
OUT.99 = 1
SPEED =
LOCATE 10
LINE #3 2, "A = ", a USING 20, 15
x = ABS(1,2) + COMMS(300)
ABS(1) = 5
"""
_PROGRAMS = [(path.name, path.read_text(encoding="utf-8")) for path in sorted(CORPUS.rglob("*.mnt")) + all_cases()]
_PROGRAMS.append(("each kind", _EACH_KIND))
_LINE_RULES = [rule for rule in RULES if rule.each_line is not None]


def _skipped_findings(text: str, dialect: Dialect) -> list[tuple[str, int, str]]:
    """Each finding a line rule makes on a line it would be skipped on: (rule, line number, code)."""
    document = parse(text, dialect)
    model = build_model(document)
    found = []
    for unit, line, facts in model.lines:
        shape = line_shape(line.syntax, facts)
        scope = LineScope(unit, line.syntax, facts, model.controller, dialect)
        for rule in _LINE_RULES:
            if dialect in rule.dialects and rule.looks_at is not None and not rule.looks_at.found_in(shape):
                found += [(rule.name, line.number, finding.diagnostic.code) for finding in rule.each_line(scope)]  # type: ignore[misc]
    return found


@pytest.mark.parametrize("dialect", list(Dialect))
def test_no_line_rule_finds_anything_on_a_line_it_is_skipped_on(dialect: Dialect) -> None:
    assert len(_PROGRAMS) > 600
    assert [(name, found) for name, text in _PROGRAMS if (found := _skipped_findings(text, dialect))] == []


@pytest.mark.parametrize("rule", [rule for rule in _LINE_RULES if rule.looks_at is not None], ids=lambda r: r.name)
def test_each_skipping_rule_reads_something(rule: Rule) -> None:
    """A rule that says it reads nothing would never run."""
    assert rule.looks_at != LineParts()


def test_a_line_of_a_kind_a_rule_reads_is_not_skipped() -> None:
    parts = LineParts(frozenset({n.Dim}), calls=True)
    assert parts.found_in((frozenset({n.Dim, n.Print}), False, False, False, False))
    assert parts.found_in((frozenset({n.Print}), False, True, False, False))
    assert not parts.found_in((frozenset({n.Print}), True, False, True, True))
    assert LineParts(arithmetic=True).found_in((frozenset({n.Print}), False, False, True, False))
