"""What the rules read: the semantic model and the index of each of its lines.

The index is built once per line with the model (``mintlang.semantic.index``);
the rules only filter it. Its nodes are the lines' position-free syntax: a rule
that reads the whole application (``Facts``) places what it reports with
``PlacedLine.span``; a rule that reads one line at a time (``LineScope``)
reports at the line's own offsets, and the analyser keeps its findings for as
long as the line's syntax does not change.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping
from operator import attrgetter
from typing import NamedTuple

from mintlang.controllers import ControllerProfile
from mintlang.diagnostics import Span
from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.records import record
from mintlang.semantic.index import IndexedLines, KeywordUse, LineFacts, Use
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n

__all__ = ["Facts", "KeywordUse", "LineParts", "LineScope", "LineShape", "Use", "gather", "line_shape"]


class LineScope(NamedTuple):
    """One logical line of one file, with what a rule may know beside it: the controller and the dialect.

    A named tuple: there is one per distinct line of every check, made in half a record's time.
    """

    unit: Unit
    syntax: n.LineSyntax
    facts: LineFacts
    controller: ControllerProfile
    dialect: Dialect  # the program's

    def writes(self, span: Span, word: str) -> bool:
        """Whether ``word`` is written at ``span`` of the line, not brought there by the macro whose name is:
        a fix that rewrites the word must not rewrite the macro's use (the macro's text would be lost)."""
        return self.syntax.text[span.start : span.end] == word


# What a line has that line rules look for: its statements' types, and whether it uses a keyword,
# calls a function, works out any arithmetic, and is labelled. Lines of one shape are many; shapes are few.
LineShape = tuple[frozenset[type], bool, bool, bool, bool]


def line_shape(syntax: n.LineSyntax, facts: LineFacts) -> LineShape:
    return (facts.kinds, bool(facts.keyword_uses), bool(facts.calls), bool(facts.arithmetic), syntax.label is not None)


@record
class LineParts:
    """What a line rule reads of a line: the analyser skips it on a line that has none of these.

    A rule that says nothing (``Rule.looks_at`` None) runs on every line. That a rule finds
    nothing on the lines it is skipped on is tested on every rule and many programs
    (``tests/analysis/test_line_rules_skip_only_lines_without_what_they_read.py``)."""

    kinds: frozenset[type] = frozenset()  # the statement types it looks at (IF .. THEN bodies included)
    keyword_uses: bool = False
    calls: bool = False
    arithmetic: bool = False  # a + - * / or MOD
    label: bool = False

    def found_in(self, shape: LineShape) -> bool:
        """Whether a line of ``shape`` has something this rule reads."""
        kinds, keyword_uses, calls, arithmetic, label = shape
        return (
            not self.kinds.isdisjoint(kinds)
            or (self.keyword_uses and keyword_uses)
            or (self.calls and calls)
            or (self.arithmetic and arithmetic)
            or (self.label and label)
        )


PlacedStatement = tuple[Unit, n.PlacedLine, n.Statement]
# The statements whole-application rules look for; few lines have any, so one pass finds them all.
_SOUGHT = frozenset({n.Jump, n.Define})


@record
class Facts:
    """The model and its lines, with the lists the rules ask for."""

    model: SemanticModel
    lines: IndexedLines
    sought: Mapping[type, tuple[PlacedStatement, ...]]  # GOSUB/GOTO and DEFINE

    def statements(self, kind: type) -> Iterable[PlacedStatement]:
        """The statements of one type, IF .. THEN bodies included, in compile order.

        GOSUB, GOTO and DEFINE are listed once for every rule that asks. Others are found
        by a pass over the lines' facts: a list would keep a line for each statement found,
        and what could not be parsed may be on every line.
        """
        found = self.sought.get(kind)
        return found if found is not None else _each_statement(self.lines, kind)

    def may_name(self, *keywords: str) -> bool:
        """Whether the text of either file, a macro's included, holds the name or an abbreviation of one of
        ``keywords``: False proves none is used, so a rule about rare keywords need not walk every keyword use
        of every check (a name edit in the editor runs the whole-application rules again)."""
        model = self.model
        texts = [model.program.source.upper()]
        if model.configuration is not None:
            texts.append(model.configuration.source.upper())
        known = database().keywords_of(model.program.dialect)
        spellings = {spelling for name in keywords for spelling in (name, *known[name].abbreviations)}
        return any(spelling in text for spelling in spellings for text in texts)

    def keyword_uses(self) -> Iterator[tuple[n.PlacedLine, KeywordUse]]:
        for _, line, facts in self.lines.where(_KEYWORD_USES):
            for use in facts.keyword_uses:
                yield line, use

    def elements(self) -> Iterator[tuple[Unit, n.PlacedLine, n.ElementRef]]:
        """Array elements read or written."""
        for unit, line, facts in self.lines.where(_ELEMENTS):
            for element in facts.elements:
                yield unit, line, element


_KEYWORD_USES = attrgetter("keyword_uses")
_ELEMENTS = attrgetter("elements")


def _each_statement(lines: IndexedLines, kind: type) -> Iterator[PlacedStatement]:
    for unit, line, facts in lines.with_kinds(frozenset({kind})):
        for statement in facts.statements:
            if type(statement) is kind:
                yield unit, line, statement


def gather(model: SemanticModel) -> Facts:
    sought: dict[type, list[PlacedStatement]] = {kind: [] for kind in _SOUGHT}
    for unit, line, facts in model.lines.with_kinds(_SOUGHT):  # most lines have none
        for statement in facts.statements:
            if type(statement) in _SOUGHT:
                sought[type(statement)].append((unit, line, statement))
    return Facts(model, model.lines, {kind: tuple(found) for kind, found in sought.items()})
