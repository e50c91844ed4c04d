"""The shape of a rule: a small class with its id, class, phase and evidence, and ``apply``.

A rule never edits text itself: it yields ``Replace`` actions (a span of the
current text and what to put there) and ``Flag`` actions (a manual item for the
line holding a span). The engine applies them in rule order, refuses
overlapping edits, and turns flags into ``REM MIGRATE:`` lines.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import ClassVar

from mintlang.diagnostics import Span
from mintlang.migrate.context import Context, FileView
from mintlang.migrate.model import Phase, RuleClass, RuleInfo
from mintlang.records import record
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n


@record
class Replace:
    """Put ``text`` in place of ``span`` (an empty span inserts)."""

    unit: Unit
    span: Span
    text: str


@record
class Flag:
    """A manual item: the line holding ``span`` gets a ``REM MIGRATE:`` line above it."""

    unit: Unit
    span: Span
    reason: str


Action = Replace | Flag


class Rule:
    """Base of every rule; subclasses set the class attributes and implement ``apply``.

    ``summary`` says what the rule matches and writes, the docstring says why,
    ``evidence`` gives the migration spec id and the manuals' lines. An ``optional``
    rule (the spec's "optional" rewrites, or a choice the user must make) only runs
    when asked for by id.
    """

    id: ClassVar[str]
    rule_class: ClassVar[RuleClass]
    phase: ClassVar[Phase]
    summary: ClassVar[str]
    evidence: ClassVar[str]
    optional: ClassVar[bool] = False
    notes: ClassVar[bool] = False  # its items are notes on the whole application, not markers above a line

    def apply(self, context: Context) -> Iterator[Action]:
        raise NotImplementedError

    @classmethod
    def info(cls) -> RuleInfo:
        return RuleInfo(cls.id, cls.rule_class, cls.phase, cls.summary, cls.evidence, cls.optional)

    # Helpers shared by the rules: they keep actions tied to the file they come from.

    @staticmethod
    def replace(file: FileView, span: Span, text: str) -> Replace:
        return Replace(file.unit, span, text)

    @staticmethod
    def flag(file: FileView, span: Span, reason: str) -> Flag:
        return Flag(file.unit, span, reason)


def selector_text(file: FileView, keyword: n.KeywordRef) -> str:
    """The axes of a keyword as written (``[0,1]``, ``.1``, ``.(a+1)``), or "" for the default axes.

    A channel glued to the keyword (``IN3``) comes back in dot form.
    """
    if keyword.selector is not None:
        return file.slice(keyword.selector.span)
    if keyword.channel is not None:
        return f".{keyword.channel}"
    return ""


def values_text(file: FileView, statement: n.KeywordStatement) -> str:
    """What follows the ``=`` of a keyword write, as written, up to the end of the statement."""
    start = statement.keyword.span.end
    text = file.slice(Span(start, statement.span.end))
    return text.split("=", 1)[1].strip() if "=" in text else ""


def same_text(first: str, second: str) -> bool:
    """Whether two statements are written alike but for spacing and case (a rule's own earlier output)."""
    return "".join(first.split()).upper() == "".join(second.split()).upper()


def keyword_refs(
    context: Context, *keywords: str
) -> Iterator[tuple[FileView, n.PlacedLine, n.Statement, n.KeywordRef]]:
    """Every use of the named keywords (canonical names), v4-only keywords included (the
    semantic index lists Mint v3 keywords only), in compile order, with its line; ``written``
    tells a write from a read. The nodes are as parsed, their spans relative to the line's
    origin (``line.span`` places one): most questions about them (which axes does this move?)
    need no copy of the line, and only the lines that name one are read."""
    wanted = frozenset(keywords)
    for file, line in context.placed(*wanted):
        for statement in n.flatten_statements(line.syntax.statements):
            if isinstance(statement, n.KeywordStatement) and statement.keyword.keyword in wanted:
                yield file, line, statement, statement.keyword
            for root in n.expressions_of(statement):
                for node in n.walk_expression(root):
                    if isinstance(node, n.KeywordRef) and node.keyword in wanted:
                        yield file, line, statement, node


def written(statement: n.Statement, keyword: n.KeywordRef) -> bool:
    """Whether ``keyword`` is the target of a write (``KW = value``) in ``statement``."""
    return isinstance(statement, n.KeywordStatement) and statement.keyword is keyword and statement.values is not None
