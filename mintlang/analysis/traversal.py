"""What the rules read: the semantic model and the index of each of its lines.

The index is built once per line with the model (``mintlang.semantic.index``);
the rules only filter it. Its nodes are the lines' position-free syntax: a rule
that reads the whole application (``Facts``) places what it reports with
``PlacedLine.span``; a rule that reads one line at a time (``LineScope``)
reports at the line's own offsets, and the analyser keeps its findings for as
long as the line's syntax does not change.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

from mintlang.controllers import ControllerProfile
from mintlang.dialect import Dialect
from mintlang.semantic.index import IndexedLines, KeywordUse, LineFacts, Use
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n

__all__ = ["Facts", "KeywordUse", "LineScope", "Use", "gather"]


@dataclass(frozen=True, slots=True)
class LineScope:
    """One logical line of one file, with what a rule may know beside it: the controller and the dialect."""

    unit: Unit
    syntax: n.LineSyntax
    facts: LineFacts
    controller: ControllerProfile
    dialect: Dialect  # the program's


PlacedStatement = tuple[Unit, n.PlacedLine, n.Statement]


@dataclass(frozen=True, slots=True)
class Facts:
    """The model and its lines, for the rules to filter."""

    model: SemanticModel
    lines: IndexedLines

    def statements(self, kind: type) -> Iterator[PlacedStatement]:
        """The statements of one type, IF .. THEN bodies included, in compile order.

        Found by a pass over the lines' facts each time, not kept in a list: the lines are
        made as they are read, and a list would keep one for every statement found (every
        line of a file of broken lines)."""
        for unit, line, facts in self.lines:
            if kind in facts.kinds:
                for statement in facts.statements:
                    if type(statement) is kind:
                        yield unit, line, statement

    def keyword_uses(self) -> Iterator[tuple[n.PlacedLine, KeywordUse]]:
        for _, line, facts in self.lines:
            for use in facts.keyword_uses:
                yield line, use

    def elements(self) -> Iterator[tuple[Unit, n.PlacedLine, n.ElementRef]]:
        """Array elements read or written."""
        for unit, line, facts in self.lines:
            for element in facts.elements:
                yield unit, line, element


def gather(model: SemanticModel) -> Facts:
    return Facts(model, model.lines)
