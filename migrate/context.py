"""What a rule sees: the files of one application, parsed as Mint v3, with the semantic model.

The engine builds a new ``Context`` for every pass, from the current text, so a
rule always looks at spans of the text it edits. Helpers here answer the
questions several rules ask (where does this line start, what is its
indentation, which newline does the file use, does the target controller have
this keyword), so no rule re-derives them.

A line gets spans with file offsets (``PlacedLine.absolute``, a copy of every
node) only when a rule asks for it: copying every line of a large file for each
of a dozen passes cost more than the parse. So rules name what they look for
(``statements(n.Dim)``, ``statements("SCALE")``): each line's tags, worked out
once per text it was parsed from (``LineTags``), say whether it can hold it,
and only those lines are copied. A tag is a superset test; the rule still
checks each statement it gets.
"""

from __future__ import annotations

import re
from array import array
from bisect import bisect_right
from collections import defaultdict
from collections.abc import Callable, Hashable, Iterable, Iterator, Mapping, Sequence
from dataclasses import field
from functools import cached_property, partial, wraps
from itertools import chain, groupby
from operator import attrgetter, itemgetter
from typing import Any, TypeVar, cast

import mintlang
from mintlang.caching import Shelf
from mintlang.controllers import ControllerProfile, profile
from mintlang.diagnostics import LineIndex, Span
from mintlang.keyworddb import database
from mintlang.keyworddb.load import KeywordDatabase
from mintlang.records import record
from mintlang.semantic.index import KeywordUse, Use, index_syntax, line_facts
from mintlang.semantic.index import clear_cache as forget_facts
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n
from mintlang.syntax.lines import MacroDefinition
from mintlang.syntax.packed import PackedLines
from mintlang.syntax.parser import Document
from mintlang.syntax.reread import Replaced, reread

T = TypeVar("T")
C = TypeVar("C", bound=Callable[..., Any])

_NEWLINE = re.compile(r"\r\n|\r|\n")
MARKER = "REM MIGRATE:"
# The commands that must be the first line of their file, before any REM: AUTO in the configuration file
# (v4:6647-6648, v3:5838), PROTECT in the program (v4:15393, v3:11079). Nothing the migrator writes goes
# above one that opens a file, in either file: it knows a file's role only from its name, and where the
# controller ignores the command (AUTO in a program, v4:6648) keeping it first changes nothing.
OPENING_COMMANDS = frozenset({"AUTO", "PROTECT"})
# What a marker written below the line it marks says first: the line opening a file (``OPENING_COMMANDS``)
# gets its markers below it, as a line inserted above AUTO or PROTECT undoes it (v4:6648, v3:11092).
LINE_ABOVE = "(line above)"
# A manual item's line: ``REM MIGRATE: <rule>: <reason>``, or ``REM MIGRATE: <rule>: (line above) <reason>``.
MARKER_LINE = re.compile(
    rf"^[ \t]*{re.escape(MARKER)}[ \t]*(?P<rule>[A-Z]+-[A-Z0-9-]+):[ \t]*"
    rf"(?P<above>{re.escape(LINE_ABOVE)}[ \t]*)?(?P<reason>.*?)[ \t]*$"
)


MARKER_LENGTH = 255  # the longest line a controller downloads, comments included (000:18455)
CUT = "..."  # the end of a marker cut to MARKER_LENGTH: ASCII, as the file's encoding may have no ellipsis


def marker_text(rule: str, reason: str, *, above: bool = False) -> str:
    """A marker line without indentation or line end; ``above`` for one that marks the line above it.

    A reason quoting a long line (a number of 5,000 digits) is cut: the marker would stop the download."""
    text = f"{MARKER} {rule}: {LINE_ABOVE + ' ' if above else ''}{reason}"
    return text if len(text) <= MARKER_LENGTH else text[: MARKER_LENGTH - len(CUT)] + CUT


def marks_above(found: re.Match[str]) -> bool:
    """Whether the marker ``MARKER_LINE`` found marks the nearest line above it that is not a marker;
    any other marks the nearest such line below it. The one place that decides which line a marker
    marks: both migrations, X-CHECK, the report and ``--verify`` all ask it."""
    return found["above"] is not None


def marks_line_above(inserted: str) -> bool:
    """Whether the text of an insertion is a marker of the line above it (``marks_above``): it goes first
    among the insertions at its point, to stay right below that line."""
    found = MARKER_LINE.match(inserted.strip("\r\n")) if LINE_ABOVE in inserted else None
    return found is not None and marks_above(found)


def marker_insertion(text: str, offset: int, marker: str, newline: str) -> tuple[int, str] | None:
    """Where the marker line ``marker`` (``marker_text``) for the line of ``offset`` goes in ``text``, and what
    is inserted there (with that line's indentation and ``newline``): right below the line when the marker
    says so (``marks_above``: the line opening the file), else above it. None when the markers next to
    the line already hold it: a second migration writes nothing twice."""
    below = marks_line_above(marker)
    start, end = line_start(text, offset), line_end(text, offset)
    line = text[start:end]
    indentation = line[: len(line) - len(line.lstrip(" \t"))]
    for near in lines_below(text, end) if below else lines_above(text, start):
        if not near.upper().startswith(MARKER):
            break
        if near == marker:
            return None
    if not below:
        return start, f"{indentation}{marker}{newline}"
    if end == len(text):  # a last line without a line break: the file ends as it did
        return end, f"{newline}{indentation}{marker}"
    return _next_line_start(text, end), f"{indentation}{marker}{newline}"


def line_start(text: str, offset: int) -> int:
    """Offset of the start of the line of ``offset`` in ``text``."""
    return max(text.rfind("\n", 0, offset), text.rfind("\r", 0, offset)) + 1


def line_end(text: str, offset: int) -> int:
    """Offset of the line break ending the line of ``offset`` in ``text`` (or of the end of the text)."""
    found = _NEWLINE.search(text, offset)
    return found.start() if found else len(text)


def lines_above(text: str, start: int) -> Iterator[str]:
    """The lines of ``text`` above the line starting at ``start``, nearest first, stripped."""
    while start > 0:
        end = start - (2 if start >= 2 and text.startswith("\r\n", start - 2) else 1)
        previous = line_start(text, end)
        yield text[previous:end].strip()
        start = previous


def lines_below(text: str, end: int) -> Iterator[str]:
    """The lines of ``text`` below the line whose line break is at ``end``, nearest first, stripped."""
    while end < len(text):
        start = _next_line_start(text, end)
        end = line_end(text, start)
        yield text[start:end].strip()


def _next_line_start(text: str, end: int) -> int:
    """Where the line after the line break at ``end`` starts."""
    return end + (2 if text.startswith("\r\n", end) else 1)


# Tags of a line besides its node types and names (see ``LineTags``): tuples, which no name equals.
LABEL = ("label",)  # the line has a label
FRACTION = ("fraction",)  # a number on the line is no integer
MACRO = ("macro",)  # a macro is used on the line: a statement's text is then the macro's name


def operator_tag(symbol: str) -> tuple[str, str]:
    """The tag of a line using a unary or binary operator (``operator_tag("~")``)."""
    return ("operator", symbol)


def statement_tag(keyword: str) -> tuple[str, str]:
    """The tag of a line with a statement of ``keyword`` (``SCALE = 2``, ``GO``): the keyword's own
    tag also stands for its reads (``PAUSE IDLE``), which a statement rule need not copy."""
    return ("statement", keyword)


def read_tag(keyword: str) -> tuple[str, str]:
    """The tag of a line reading the keyword ``keyword`` in an expression (``a = MOVEA``,
    ``PAUSE IDLE``): a rule after the reads alone need not copy every line that writes it."""
    return ("read", keyword)


def constant_tag(name: str) -> tuple[str, str]:
    """The tag of a line using the constant ``name`` (upper case, ``_SERVO``)."""
    return ("constant", name)


def name_tag(name: str) -> tuple[str, str]:
    """The tag of a line writing or reading the user name ``name`` (by its identity: the first
    ten characters, upper case), apart from the keyword names so that asking for those by what
    they are (``Context.mentioned``) never brings in every line that uses a variable."""
    return ("name", n.identity(name))


class LineTags:
    """What each line mentions, worked out once per text it was parsed from for a whole run: the
    types of its statements and expressions, the keywords and functions it names, ``constant_tag``
    of its constants, ``statement_tag`` of its keyword statements, ``read_tag`` of its keyword
    reads, ``name_tag`` of its user names, ``operator_tag`` of its operators, ``LABEL`` and
    ``FRACTION`` (``Context`` adds ``MACRO``, which depends on the macros defined above the line).
    Keyed by ``PlacedLine.content``, never by the shared syntax (see ``mintlang.caching``).

    A line's tags are a tuple, each distinct tuple and tag held once (a frozenset apiece took 15
    times the program's size), and only those of the text last asked about are kept: the versions
    of lines a pass replaced held 7 times the program's size by the end of a run."""

    def __init__(self) -> None:
        self._known: dict[Hashable, tuple[object, ...]] = {}
        self._tags: dict[object, object] = {}
        self._tuples: dict[tuple[object, ...], tuple[object, ...]] = {}

    def clear(self) -> None:
        """Forget every line's tags: no pass that asks for them is to come."""
        self._known, self._tags, self._tuples = {}, {}, {}

    def of_text(self, lines: Iterable[n.PlacedLine]) -> list[tuple[object, ...]]:
        """The distinct tags of each of ``lines``, the lines of a whole text; the tags of other
        lines are forgotten."""
        earlier, self._known = self._known, {}
        return [self._of(line, earlier) for line in lines]

    def _of(self, line: n.PlacedLine, earlier: dict[Hashable, tuple[object, ...]]) -> tuple[object, ...]:
        tags = self._known.get(line.content)
        if tags is None:
            tags = earlier.get(line.content)
        if tags is None:
            shared = self._tags.setdefault
            found = tuple([shared(tag, tag) for tag in _tags(line.syntax)])
            tags = self._tuples.setdefault(found, found)
        self._known[line.content] = tags
        return tags


def _tags(syntax: n.LineSyntax) -> frozenset[object]:
    found: set[object] = set() if syntax.label is None else {LABEL}
    add = found.add
    for statement in n.flatten_statements(syntax.statements):
        kind = type(statement)
        add(kind)
        if kind is n.KeywordStatement:
            add(statement.keyword.keyword)  # type: ignore[union-attr]
            add(statement_tag(statement.keyword.keyword))  # type: ignore[union-attr]
        elif kind is n.FunctionStatement:
            add(statement.call.function)  # type: ignore[union-attr]
        elif kind is n.Assignment or kind is n.Input:
            add(name_tag(statement.target.name.text))  # type: ignore[union-attr]
        elif kind is n.For:
            add(name_tag(statement.variable.text))  # type: ignore[union-attr]
        elif kind is n.Dim or kind is n.BareName:
            add(name_tag(statement.name.text))  # type: ignore[union-attr]
        for root in n.expressions_of(statement):
            for node in n.walk_expression(root):
                kind = type(node)
                add(kind)
                if kind is n.KeywordRef:
                    add(node.keyword)  # type: ignore[union-attr]
                    add(read_tag(node.keyword))  # type: ignore[union-attr]
                elif kind is n.Call:
                    add(node.function)  # type: ignore[union-attr]
                elif kind is n.ConstantRef:
                    add(constant_tag(node.name))  # type: ignore[union-attr]
                elif kind is n.VariableRef or kind is n.ElementRef:
                    add(name_tag(node.name.text))  # type: ignore[union-attr]
                elif kind is n.Binary or kind is n.Unary:
                    add(operator_tag(node.operator))  # type: ignore[union-attr]
                elif kind is n.Number and not float(node.value).is_integer():  # type: ignore[union-attr]
                    add(FRACTION)
    return frozenset(found)


@record(slots=False)
class FileView:
    """One file of the application as the current pass sees it."""

    unit: Unit
    text: str
    document: Document

    def line(self, index: int) -> n.Line:
        """Line ``index`` of ``document.placed`` with file offsets, copied on first use (a node of
        its own at every place, as ``Document.lines`` has, which copies every line at once)."""
        lines = self._lines
        line = lines[index]
        if line is None:
            line = lines[index] = self.document.placed[index].absolute()
        return line

    def keyword_uses(self, index: int) -> tuple[KeywordUse, ...]:
        """The keyword uses of line ``index``, nodes of ``line(index)``: the semantic index of that
        line alone (``index_syntax`` reads a document's ``lines`` and nothing else)."""
        uses = self._uses.get(index)
        if uses is None:
            alone = cast(Document, _Lines((self.line(index),)))
            uses = self._uses[index] = index_syntax([(self.unit, alone)]).keyword_uses
        return uses

    @cached_property
    def line_starts(self) -> list[int]:
        """Where each line's syntax starts (``line(index).span.start``), for bisecting an offset."""
        return [line.origin + line.syntax.span.start for line in self.document.placed]

    @cached_property
    def expanded(self) -> frozenset[int]:
        """The indices of the lines where a macro is used."""
        return frozenset(bisect_right(self.line_starts, use.span.start) - 1 for use in self.document.expansions)

    @cached_property
    def _lines(self) -> list[n.Line | None]:
        return [None] * len(self.document.placed)

    @cached_property
    def _uses(self) -> dict[int, tuple[KeywordUse, ...]]:
        return {}

    @cached_property
    def newline(self) -> str:
        """The file's own line break (the first one found; ``\\n`` for a one-line file)."""
        found = _NEWLINE.search(self.text)
        return found.group() if found else "\n"

    @cached_property
    def _line_index(self) -> LineIndex:
        """Where the text's lines start, in machine integers: the document's own index reads them
        through a Python sequence at every step of a bisection, and each marker takes several."""
        return LineIndex(self.text)

    def line_start(self, offset: int) -> int:
        index = self._line_index
        return index.line_start(index.position(offset).line)

    def line_end(self, offset: int) -> int:
        """Offset of the line break ending the line of ``offset`` (or of the end of the text)."""
        return line_end(self.text, offset)

    def indentation(self, offset: int) -> str:
        start = self.line_start(offset)
        line = self.text[start : self.line_end(offset)]
        return line[: len(line) - len(line.lstrip(" \t"))]

    def line_number(self, offset: int) -> int:
        return self._line_index.position(offset).line

    def lines_above(self, offset: int) -> Iterator[str]:
        """The physical lines above the line of ``offset``, nearest first, stripped."""
        return lines_above(self.text, self.line_start(offset))

    @cached_property
    def opening(self) -> n.Line | None:
        """The line of the command that must stay the first of the file, REM lines included
        (``OPENING_COMMANDS``), or None. Nothing the migrator writes may go above it."""
        for index, placed in enumerate(self.document.placed):
            syntax = placed.syntax
            if not syntax.statements and syntax.label is None:
                continue
            first = syntax.statements[0] if syntax.statements else None
            opens = isinstance(first, n.KeywordStatement) and first.keyword.keyword in OPENING_COMMANDS
            return self.line(index) if opens else None
        return None

    @cached_property
    def after_opening(self) -> Span | None:
        """The separator (`` : ``) between the command that opens the file and a statement after
        it on its line (``AUTO : a = 1``), or None: what must go below that command breaks the
        line there, as a line end separates statements as ``:`` does."""
        line = self.opening
        if line is None or len(line.statements) < 2:
            return None
        command, following = line.statements[:2]
        return Span(command.span.end, following.span.start)

    def lines_below(self, offset: int) -> Iterator[str]:
        """The physical lines below the line of ``offset``, nearest first, stripped."""
        return lines_below(self.text, self.line_end(offset))

    def markers_on(self, offset: int) -> Iterator[str]:
        """The rules of the ``REM MIGRATE:`` lines that mark the line of ``offset`` (``marks_above``):
        among the markers right above it and right below it, nearest first."""
        for lines, above in ((self.lines_above(offset), False), (self.lines_below(offset), True)):
            for line in lines:
                found = MARKER_LINE.match(line)
                if found is None:
                    break
                if marks_above(found) is above:
                    yield found["rule"]

    def in_opening_command(self, offset: int) -> bool:
        """Whether ``offset`` lies in the command that opens the file (``opening``), not in a statement
        after it on its line: a marker for it goes below it and says so (``LINE_ABOVE``)."""
        line = self.opening
        if line is None or self.line_start(line.span.start) != self.line_start(offset):
            return False
        split = self.after_opening
        return split is None or offset < split.start

    def slice(self, span: Span) -> str:
        return self.text[span.start : span.end]

    def last_on_its_line(self, statement: n.Statement) -> bool:
        """Whether ``statement`` can become a REM without commenting out other code: nothing but a
        comment after it, and nothing or a ``:`` before it (``RESET : COMMSON``; not ``THEN COMMSON``,
        whose IF would be left without a statement)."""
        before = self.text[self.line_start(statement.span.start) : statement.span.start].strip()
        after = self.text[statement.span.end : self.line_end(statement.span.end)].strip()
        return (before == "" or before.endswith(":")) and (
            after == "" or after.upper().startswith(("REM", ": REM", ":REM"))
        )


@record
class _Lines:
    """One line standing in for a document, for ``index_syntax``."""

    lines: tuple[n.Line, ...]


# A statement with the ones written right before and after it on its line (``Context.neighbours``).
Neighbours = tuple[FileView, n.Statement | None, n.Statement, n.Statement | None]


class Unreadable(Exception):
    """Building the semantic model failed: a bug in reading the files, not in the rule that asked
    for the model first (the engine reports it so; the exception is the cause)."""


@record(slots=False)
class Context:
    """The application (configuration file, if any, then program) for one pass of the engine."""

    files: Mapping[Unit, FileView]
    controller: ControllerProfile
    tags: LineTags = field(default_factory=LineTags, repr=False, compare=False)
    # The per-line caches of the run's Mint v4 readings (``rules.manual.v4_errors``): X-CHECK reads
    # the text X-COMMENTED read, with the markers it led to, so it parses only those afresh.
    v4_shelf: Shelf = field(default_factory=Shelf, repr=False, compare=False)
    _memo: dict[tuple[Hashable, ...], Any] = field(default_factory=dict, init=False, repr=False, compare=False)

    @classmethod
    def build(
        cls, texts: Mapping[Unit, str], controller: str, tags: LineTags | None = None, v4_shelf: Shelf | None = None
    ) -> Context:
        """The context of ``texts``; ``tags`` are those of earlier passes of the run, whose
        unchanged lines need not be walked again, and ``v4_shelf`` holds its Mint v4 readings' lines."""
        return cls.reading(texts, controller, tags, v4_shelf, {})

    @classmethod
    def reading(
        cls,
        texts: Mapping[Unit, str],
        controller: str,
        tags: LineTags | None,
        v4_shelf: Shelf | None,
        earlier: Mapping[Unit, Earlier],
    ) -> Context:
        """``build``, where ``earlier`` holds for some files the reading of an earlier text and the edits
        that made the text of ``texts`` from it: only the lines those touched are read again (``reread``)."""
        configuration = None
        if Unit.CONFIGURATION in texts:
            configuration = _read(texts[Unit.CONFIGURATION], earlier.get(Unit.CONFIGURATION), None)
        program = _read(
            texts[Unit.PROGRAM], earlier.get(Unit.PROGRAM), configuration.macros if configuration is not None else None
        )
        documents = {Unit.PROGRAM: program}
        if configuration is not None:
            documents[Unit.CONFIGURATION] = configuration
        files = {unit: FileView(unit, texts[unit], documents[unit]) for unit in texts}
        tags = tags if tags is not None else LineTags()
        return cls(files, profile(controller), tags, v4_shelf if v4_shelf is not None else Shelf())

    def lines_read(self) -> Iterable[Hashable]:
        """What the per-line caches hold of this context's lines: each logical line's content and text
        (the parser's key), each physical line's text (the lexer's). A re-read that took most lines over
        from an earlier reading looked none of them up (``mintlang.caching.keeping_what_it_uses``)."""
        found: list[Iterable[Hashable]] = []
        for file in self.files.values():
            placed = file.document.placed
            if isinstance(placed, PackedLines):
                _, _, syntaxes, contents = placed.columns()
                found += (contents, map(_TEXT, syntaxes))
            else:
                found += (map(_CONTENT, placed), map(_SYNTAX_TEXT, placed))
            found.append(map(_TEXT, map(_LEXED, file.document.physical)))
        return chain.from_iterable(found)

    @cached_property
    def model(self) -> mintlang.SemanticModel:
        """The semantic model, built when a rule first asks: the abbreviations need none, so the
        text as first read, which they change in most programs, never has one built."""
        configuration = self.files.get(Unit.CONFIGURATION)
        documents = (self.files[Unit.PROGRAM].document, None if configuration is None else configuration.document)
        try:
            return mintlang.build_model(*documents, self.controller.controller)
        except Exception as error:  # any failure here is the reader's, reported as such
            raise Unreadable from error

    def forget_copies(self) -> None:
        """Forget what the rules of a phase asked for (lines with file offsets, their keyword uses,
        the answers of ``memo``), keeping the text's reading and model: the next phase starts from
        this context when the last pass changed nothing, and the copies the phase before it made
        held a fifth of the insertions' peak while its rules asked for other lines."""
        self._memo.clear()
        self.forget_line_copies()

    def forget_line_copies(self) -> None:
        """Forget the lines a rule copied and their keyword uses: the engine calls it after each rule,
        as the next asks for lines of its own, and a pass's copies kept to its end were a run's peak."""
        for file in self.files.values():
            for copies in ("_lines", "_uses"):
                file.__dict__.pop(copies, None)

    def forget_model(self) -> None:
        """Drop the semantic model and what the run keeps of each line for the next pass: its facts
        (the model's per-line index, which the per-line cache would otherwise keep alive alone), what
        the pass's Mint v3 check found in it, and its tags, which this context has indexed already;
        and the lines the pass copied (a slot for every line). A rule about to build something as
        large beside them (a Mint v4 reading of the text) frees them first, once its own questions
        are answered. A rule asking for the model or a line later builds it again, and a next pass
        walks every line for its tags, facts and findings again: the last phase reads no tags and
        checks no line as Mint v3, so only a pass of the same phase would (a line split)."""
        from mintlang.analysis.analyser import clear_cache as forget_findings  # noqa: PLC0415 - loaded by the first check

        self.__dict__.pop("model", None)
        self.tags.clear()  # those of this context's lines are indexed when it is first asked about one
        forget_facts()  # in a run (``apart``), the run's own lines; else the process's, which costs time only
        forget_findings()
        self.forget_line_copies()

    def memo(self, compute: Callable[..., T], *args: Hashable) -> T:
        """``compute(self, *args)``, worked out once per pass: rules ask some whole-application
        questions at every statement, and rescanning each time made large files quadratic."""
        key = (compute, *args)
        if key not in self._memo:
            self._memo[key] = compute(self, *args)
        return self._memo[key]

    @property
    def db(self) -> KeywordDatabase:
        return database()

    def placed(self, *wanted: object) -> Iterator[tuple[FileView, n.PlacedLine]]:
        """``lines(*wanted)`` as parsed, spans relative to each line's ``origin``: for a question
        whose answer needs no nodes with file offsets."""
        for file, index in self._located(self._positions(wanted)):
            yield file, file.document.placed[index]

    def lines(self, *wanted: object) -> Iterator[tuple[FileView, n.Line]]:
        """The lines that have one of the ``wanted`` tags (see ``LineTags``), in compile order, with
        file offsets. No tag, no line: a rule names what it looks for."""
        for file, index in self._located(self._positions(wanted)):
            yield file, file.line(index)

    def statements(self, *wanted: object) -> Iterator[tuple[FileView, n.Line, n.Statement]]:
        """The statements of the lines with one of the ``wanted`` tags, in compile order
        (configuration first), IF .. THEN bodies included.

        Each line has a node of its own at every place (``FileView.line``), so
        ``mintlang.syntax.parents`` can find what encloses an expression inside one."""
        for file, line in self.lines(*wanted):
            for statement in n.flatten_statements(line.statements):
                yield file, line, statement

    def neighbours(self, *wanted: object) -> Iterator[Neighbours]:
        """Every statement of the lines with one of the ``wanted`` tags, in compile order, with the
        ones written right before and after it on its line (None at either end; IF .. THEN bodies
        count in line order). A line is told by its place, (file, line number): equal lines share
        their syntax, so no statement can name one."""
        for _, group in groupby(self.statements(*wanted), key=_line_place):
            found = [(file, statement) for file, _, statement in group]
            line: list[n.Statement | None] = [None, *(statement for _, statement in found), None]
            for position, (file, statement) in enumerate(found, start=1):
                yield file, line[position - 1], statement, line[position + 1]

    def keyword_uses(self, *keywords: str) -> Iterator[tuple[FileView, KeywordUse]]:
        """Uses of the named keywords (canonical v3 names), however they were spelled, in compile order."""
        return self._keyword_uses(frozenset(keywords), keywords)

    def keyword_reads(self, *keywords: str) -> Iterator[tuple[FileView, KeywordUse]]:
        """The uses of ``keyword_uses`` that read the keyword's value (``Use.READ``)."""
        uses = self._keyword_uses(frozenset(keywords), map(read_tag, keywords))
        return ((file, use) for file, use in uses if use.use is Use.READ)

    def _keyword_uses(self, wanted: frozenset[str], tags: Iterable[object]) -> Iterator[tuple[FileView, KeywordUse]]:
        for file, index in self._located(self._positions(tags)):
            for use in file.keyword_uses(index):
                if use.keyword.keyword in wanted:
                    yield file, use

    def mentioned(self, keep: Callable[[str], bool]) -> list[str]:
        """The keyword and function names written anywhere in the application that ``keep``
        accepts: the ``wanted`` of a rule that asks for keywords by what they are (not a Mint v4
        keyword ...), not by a list."""
        return [tag for tag in self._tagged if type(tag) is str and keep(tag)]

    def names(self, keep: Callable[[str], bool]) -> list[str]:
        """The user names written anywhere in the application (by identity, see ``name_tag``) that
        ``keep`` accepts: a rule that needs the symbol table only for some names asks first."""
        return [tag[1] for tag in self._tagged if type(tag) is tuple and tag[0] == "name" and keep(tag[1])]

    def spellings(self, identities: Iterable[str]) -> set[str]:
        """How the user names of these identities are written, read from the lines that use them:
        the spellings the symbol table would give, without building the semantic model."""
        wanted = frozenset(identities)
        return {
            event.name.text
            for file, line in self.placed(*map(name_tag, wanted))
            for event in line_facts(file.unit, line).names
            if event.name.identity in wanted
        }

    def _located(self, positions: Iterable[int]) -> Iterator[tuple[FileView, int]]:
        """Each of ``positions`` in compile order (ascending) as its file and its index there: worked
        out from where each file starts, where a pair for every line held 3.5 times the program's size."""
        files = iter(self.compiled)
        file = next(files)
        start, end = 0, len(file.document.placed)
        for position in positions:
            while position >= end:
                file = next(files)
                start, end = end, end + len(file.document.placed)
            yield file, position - start

    @cached_property
    def _tagged(self) -> dict[object, array[int]]:
        """Each tag with the positions in compile order of the lines that have it, in order (machine
        integers: a list of Python ones held 3 times the program's size)."""
        found: defaultdict[object, array[int]] = defaultdict(partial(array, "I"))
        tags = self.tags.of_text([line for file in self.compiled for line in file.document.placed])
        position = 0
        for file in self.compiled:
            expanded = file.expanded
            for index in range(len(file.document.placed)):
                line_tags = tags[position]
                for tag in (*line_tags, MACRO) if index in expanded else line_tags:
                    found[tag].append(position)
                position += 1
        return dict(found)

    @cached_property
    def compiled(self) -> tuple[FileView, ...]:
        """The files in compile order: the configuration file first."""
        return tuple(self.files[unit] for unit in (Unit.CONFIGURATION, Unit.PROGRAM) if unit in self.files)

    def _positions(self, wanted: Iterable[object]) -> Sequence[int]:
        tagged = self._tagged
        found = [tagged[tag] for tag in wanted if tag in tagged]
        if len(found) == 1:
            return found[0]
        return sorted(set().union(*found))  # none: no line

    def supports(self, keyword: str) -> bool:
        """Whether the target controller has the v4 keyword (its "Controllers Supported" list)."""
        entry = self.db.keywords.get(keyword.upper())
        return entry is not None and entry.available_on(self.controller.controller)


# A file's reading of an earlier text, and the edits since: each replaced ``start:end`` of that text
# with so many characters (``mintlang.syntax.reread``).
Earlier = tuple[Document, Sequence[Replaced]]
_CONTENT, _SYNTAX_TEXT, _TEXT = attrgetter("content"), attrgetter("syntax.text"), attrgetter("text")
_LEXED = itemgetter(1)


def _read(text: str, earlier: Earlier | None, macros: Mapping[str, MacroDefinition] | None) -> Document:
    """``text`` read as Mint v3: its earlier reading's lines taken over where ``reread`` can."""
    if earlier is not None and not macros:
        document = reread(earlier[0], text, earlier[1])
        if document is not None:
            return document
    return mintlang.parse(text, "v3", macros=macros)


def _line_place(found: tuple[FileView, n.Line, n.Statement]) -> tuple[Unit, int]:
    file, line, _ = found
    return file.unit, line.number


def per_pass(compute: C) -> C:
    """``compute(context, *args)`` worked out once per context and arguments (which must be
    hashable; see ``Context.memo``); its result is shared, so callers must not change it."""

    @wraps(compute)
    def cached(context: Context, *args: Hashable) -> object:
        return context.memo(compute, *args)

    return cast(C, cached)
