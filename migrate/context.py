"""What a rule sees: the files of one application, parsed as Mint v3, with the semantic model.

The engine builds a new ``Context`` for every pass, from the current text, so a
rule always looks at spans of the text it edits. Helpers here answer the
questions several rules ask (where does this line start, what is its
indentation, which newline does the file use, does the target controller have
this keyword), so no rule re-derives them.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, field
from functools import cached_property, wraps
from itertools import groupby
from typing import Any, TypeVar

import mintlang
from mintlang.controllers import ControllerProfile, profile
from mintlang.diagnostics import Span
from mintlang.keyworddb import database
from mintlang.keyworddb.load import KeywordDatabase
from mintlang.semantic.index import KeywordUse
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n
from mintlang.syntax.parser import Document

T = TypeVar("T")

_NEWLINE = re.compile(r"\r\n|\r|\n")
MARKER = "REM MIGRATE:"
# A manual item's line: ``REM MIGRATE: <rule>: <reason>``.
MARKER_LINE = re.compile(rf"^[ \t]*{re.escape(MARKER)}[ \t]*(?P<rule>[A-Z]+-[A-Z0-9-]+):[ \t]*(?P<reason>.*?)[ \t]*$")


@dataclass(frozen=True)
class FileView:
    """One file of the application as the current pass sees it."""

    unit: Unit
    text: str
    document: Document

    @cached_property
    def newline(self) -> str:
        """The file's own line break (the first one found; ``\\n`` for a one-line file)."""
        found = _NEWLINE.search(self.text)
        return found.group() if found else "\n"

    def line_start(self, offset: int) -> int:
        index = self.document.line_index
        return index.line_start(index.position(offset).line)

    def line_end(self, offset: int) -> int:
        """Offset of the line break ending the line of ``offset`` (or of the end of the text)."""
        found = _NEWLINE.search(self.text, offset)
        return found.start() if found else len(self.text)

    def indentation(self, offset: int) -> str:
        start = self.line_start(offset)
        line = self.text[start : self.line_end(offset)]
        return line[: len(line) - len(line.lstrip(" \t"))]

    def line_number(self, offset: int) -> int:
        return self.document.line_index.position(offset).line

    def lines_above(self, offset: int) -> Iterator[str]:
        """The physical lines above the line of ``offset``, nearest first, stripped."""
        start = self.line_start(offset)
        while start > 0:
            previous = self.line_start(start - 1)
            yield self.text[previous:start].strip()
            start = previous

    @cached_property
    def opening(self) -> n.Line | None:
        """The line of the command that must stay the first of the file, REM lines included, or
        None: AUTO in a configuration file (v4:6647-6649, v3:5838), PROTECT in a program
        (v4:15393, v3:11079). Nothing the migrator writes may go above it."""
        word = "AUTO" if self.unit is Unit.CONFIGURATION else "PROTECT"
        for line in self.document.lines:
            if not line.statements and line.label is None:
                continue
            first = line.statements[0] if line.statements else None
            return line if isinstance(first, n.KeywordStatement) and first.keyword.keyword == word else None
        return None

    def markers_above(self, offset: int) -> Iterator[str]:
        """The rules of the ``REM MIGRATE:`` lines right above the line of ``offset``, nearest first."""
        for above in self.lines_above(offset):
            found = MARKER_LINE.match(above)
            if found is None:
                return
            yield found["rule"]

    def slice(self, span: Span) -> str:
        return self.text[span.start : span.end]

    def statement_alone(self, statement: n.Statement) -> bool:
        """Whether ``statement`` is the only thing on its line apart from a trailing comment."""
        before = self.text[self.line_start(statement.span.start) : statement.span.start]
        after = self.text[statement.span.end : self.line_end(statement.span.end)].strip()
        return before.strip() == "" and (after == "" or after.upper().startswith(("REM", ": REM", ":REM")))


# A statement with the ones written right before and after it on its line (``Context.neighbours``).
Neighbours = tuple[FileView, n.Statement | None, n.Statement, n.Statement | None]


@dataclass(frozen=True)
class Context:
    """The application (configuration file, if any, then program) for one pass of the engine."""

    files: Mapping[Unit, FileView]
    model: mintlang.SemanticModel
    controller: ControllerProfile
    _memo: dict[Callable[[Any], Any], Any] = field(default_factory=dict, init=False, repr=False, compare=False)

    @classmethod
    def build(cls, texts: Mapping[Unit, str], controller: str) -> Context:
        configuration = None
        if Unit.CONFIGURATION in texts:
            configuration = mintlang.parse(texts[Unit.CONFIGURATION], "v3")
        program = mintlang.parse(
            texts[Unit.PROGRAM], "v3", macros=configuration.macros if configuration is not None else None
        )
        documents = {Unit.PROGRAM: program}
        if configuration is not None:
            documents[Unit.CONFIGURATION] = configuration
        files = {unit: FileView(unit, texts[unit], documents[unit]) for unit in texts}
        model = mintlang.build_model(program, configuration, controller)
        return cls(files, model, profile(controller))

    def memo(self, compute: Callable[[Context], T]) -> T:
        """``compute(self)``, worked out once per pass: rules ask some whole-application
        questions at every statement, and rescanning each time made large files quadratic."""
        if compute not in self._memo:
            self._memo[compute] = compute(self)
        return self._memo[compute]

    @property
    def db(self) -> KeywordDatabase:
        return database()

    def statements(self) -> Iterator[tuple[FileView, n.Line, n.Statement]]:
        """Every statement in compile order (configuration first), IF .. THEN bodies included.

        They come from ``Document.lines``, a node of its own at every place, so
        ``mintlang.syntax.parents`` can find what encloses an expression inside one."""
        for unit, line, statement in self.model.index.statements:
            yield self.files[unit], line, statement

    def neighbours(self) -> Iterator[Neighbours]:
        """Every statement in compile order with the ones written right before and after it on its
        line (None at either end; IF .. THEN bodies count in line order). A line is told by its
        place, (file, line number): equal lines share their syntax, so no statement can name one."""
        for _, group in groupby(self.statements(), key=_line_place):
            found = [(file, statement) for file, _, statement in group]
            line: list[n.Statement | None] = [None, *(statement for _, statement in found), None]
            for position, (file, statement) in enumerate(found, start=1):
                yield file, line[position - 1], statement, line[position + 1]

    def keyword_uses(self, *keywords: str) -> Iterator[tuple[FileView, KeywordUse]]:
        """Uses of the named keywords (canonical v3 names), however they were spelled."""
        wanted = frozenset(keywords)
        for use in self.model.index.keyword_uses:
            if use.keyword.keyword in wanted:
                yield self.files[use.unit], use

    def supports(self, keyword: str) -> bool:
        """Whether the target controller has the v4 keyword (its "Controllers Supported" list)."""
        entry = self.db.keywords.get(keyword.upper())
        return entry is not None and self.controller.controller in entry.controllers


def _line_place(found: tuple[FileView, n.Line, n.Statement]) -> tuple[Unit, int]:
    file, line, _ = found
    return file.unit, line.number


def per_pass(compute: Callable[[Context], T]) -> Callable[[Context], T]:
    """``compute`` worked out once per context (see ``Context.memo``); its result is shared, so
    callers must not change it."""

    @wraps(compute)
    def cached(context: Context) -> T:
        return context.memo(compute)

    return cached
