"""Parsing a new version of a document from the previous one: only the lines an edit touched.

A language server parses the file again on every keystroke. Lexing, grouping and
placing every line again costs time in proportion to the file even when each
line's parse comes from the cache; here the text is compared with the previous
version (a binary search of common prefix and suffix, at the speed of comparing
strings), the physical lines between are lexed, the logical lines around them
grouped and parsed again, and every other line is taken over, moved by the
edit's length. The result equals ``parse`` of the new text (a property test
holds it to that); where the edit could change how lines further away read (a
``DEFINE`` in the window), it is ``parse`` of the new text.
"""

from __future__ import annotations

from array import array
from collections.abc import Mapping, Sequence

from mintlang.allocation import without_collector
from mintlang.diagnostics import Diagnostic, LineIndex, LinesAndEnd
from mintlang.dialect import Dialect
from mintlang.keyworddb.model import Controller
from mintlang.records import record
from mintlang.syntax import nodes as n
from mintlang.syntax.change import Change, Window
from mintlang.syntax.common import shared_ends
from mintlang.syntax.lexer import LexedLine, PhysicalLines, TokenStream, lex_lines
from mintlang.syntax.lines import LineGroup, MacroDefinition, groups_from, register
from mintlang.syntax.moved import LINE_NUMBER, MovedLines, bisect_left, bisect_right
from mintlang.syntax.parser import Document, ParseContext, PlacedLines, parse
from mintlang.syntax.tokens import TokenKind


@without_collector
def reparse(
    previous: Document,
    source: str,
    dialect: Dialect | str = Dialect.V4,
    *,
    macros: Mapping[str, MacroDefinition] | None = None,
    controller: Controller | str | None = None,
) -> Document:
    """``parse(source, ...)``, reading again only what changed since ``previous``."""
    context = ParseContext.of(dialect, controller, macros)
    if previous.context != context:
        return parse(source, dialect, macros=macros, controller=controller)
    return _Reparse(previous, source, context, macros or {}).document() or parse(
        source, dialect, macros=macros, controller=controller
    )


def _line_boundary(text: str, offset: int) -> bool:
    """A physical line starts at ``offset`` of ``text`` (a ``\\r`` followed by ``\\n`` is one line end)."""
    if offset in {0, len(text)}:
        return True
    before = text[offset - 1]
    return before == "\n" or (before == "\r" and text[offset] != "\n")


@record
class _Lines:
    """The physical lines ``first`` to ``end`` of the previous text, which ``window`` replaced."""

    first: int
    end: int
    window: Window


class _Reparse:
    def __init__(self, previous: Document, source: str, context: ParseContext, macros: Mapping[str, MacroDefinition]):
        self.previous = previous
        self.source = source
        self.context = context
        self.macros = macros
        self.offsets = previous.physical.offsets

    def _line_start(self, index: int) -> int:
        offsets = self.offsets
        return offsets[index] if index < len(offsets) else len(self.previous.source)

    def window(self) -> _Lines:
        """The fewest whole physical lines of the previous text that hold every changed character."""
        old, new = self.previous.source, self.source
        same_start, same_end = shared_ends(old, new)
        offsets = self.offsets
        first = max(0, bisect_right(offsets, same_start) - 1)
        end = bisect_left(offsets, len(old) - same_end)
        shift = len(new) - len(old)
        while first and not _line_boundary(new, offsets[first]):
            first -= 1  # a "\r" that ends the line before now meets a "\n"
        while end < len(offsets) and not _line_boundary(new, offsets[end] + shift):
            end += 1
        start = self._line_start(first)
        old_end = self._line_start(end)
        return _Lines(first, end, Window(start, old_end, old_end + shift, len(old)))

    def document(self) -> Document | None:
        """The new document, or None where the edit may change lines outside the window."""
        previous, source, context = self.previous, self.source, self.context
        lines_read = self.window()
        window = lines_read.window
        offsets: array[int] = array("q")
        lexed: list[LexedLine] = []
        lexer_issues: list[Diagnostic] = []
        lex_lines(source[window.start : window.new_end], context.dialect, window.start, offsets, lexed, lexer_issues)
        shift = window.shift
        physical = previous.physical.spliced(lines_read.first, lines_read.end, offsets, lexed, shift)
        line_shift = len(lexed) - (lines_read.end - lines_read.first)
        placed = previous.placed
        first_line = bisect_left(placed, lines_read.first + 1, key=LINE_NUMBER)  # the first logical line in the window
        if first_line and self._runs_into(placed[first_line - 1], lines_read.first):
            first_line -= 1  # a DIM list continued over the window's first line, or waiting to be
        restart = placed[first_line].number - 1 if first_line < len(placed) else len(physical)
        restart = min(restart, lines_read.first)
        groups, resume, old_resume = self._regroup(physical, restart, lines_read.first + len(lexed), line_shift)
        old_end_line = bisect_left(placed, old_resume + 1, key=LINE_NUMBER)
        regroup_start = physical.offsets[restart] if restart < len(physical) else len(source)
        old_regroup_end = self._line_start(old_resume)
        new_regroup_end = physical.offsets[resume] if resume < len(physical) else len(source)
        if any(regroup_start <= d.name_span.start < old_regroup_end for d in previous.definitions):
            return None  # a macro defined there: the lines after may read differently now
        lines = PlacedLines(self._visible_at(regroup_start))
        lines.parse(groups, context)
        if lines.definitions:
            return None
        change = Change(
            start=regroup_start,
            old_end=old_regroup_end,
            new_end=new_regroup_end,
            previous_length=len(previous.source),
            first_line=first_line,
            old_lines=old_end_line - first_line,
            new_lines=len(lines.syntaxes),
            line_shift=line_shift,
        )
        definitions = tuple(
            definition if definition.name_span.start < regroup_start else definition.shifted(shift)
            for definition in previous.definitions
        )
        visible = dict(self.macros)
        register(visible, list(definitions))
        return Document(
            source,
            context.dialect,
            TokenStream(physical),
            physical,
            MovedLines.spliced(placed, (first_line, old_end_line), lines.placed(), shift, line_shift),
            window.spliced(previous.lexer_issues, lexer_issues),
            change.spliced(previous.parse_issues, lines.issues()),
            visible,
            definitions,
            change.spliced(previous.expansions, lines.expansions),
            LineIndex(source, LinesAndEnd(physical.offsets, source)),
            context,
            change,
        )

    def _runs_into(self, line: n.PlacedLine, first: int) -> bool:
        """``line`` (before physical line ``first``) reaches it, or ends in a comma a DIM list would
        continue after: the edit may change where it ends."""
        last = _last_physical(line, self.offsets)
        kinds = self.previous.physical.lexed(last).kinds
        return last >= first or (bool(kinds) and kinds[-1] is TokenKind.COMMA)

    def _regroup(
        self, physical: PhysicalLines, restart: int, past: int, line_shift: int
    ) -> tuple[list[LineGroup], int, int]:
        """The logical lines from ``restart`` until the grouping meets the previous one again after
        the window (which ends before new line ``past``): the groups, and where the grouping met the
        previous one, in the new and the previous lines."""
        groups: list[LineGroup] = []
        previous_ends = _GroupEnds(self.previous.placed, self.offsets)
        for group, after in groups_from(physical, restart):
            groups.append(group)
            if after >= past and after - line_shift in previous_ends:
                return groups, after, after - line_shift
        return groups, len(physical), len(self.offsets)

    def _visible_at(self, offset: int) -> dict[str, MacroDefinition]:
        """The macros a line at ``offset`` sees: those given, then those the file defined above it."""
        visible = dict(self.macros)
        register(visible, [d for d in self.previous.definitions if d.name_span.start < offset])
        return visible


def _last_physical(line: n.PlacedLine, offsets: Sequence[int]) -> int:
    """The index of the last physical line of logical line ``line`` (a DIM list may take several)."""
    return bisect_right(offsets, line.origin + max(line.syntax.span.end - 1, 0)) - 1


class _GroupEnds:
    """Whether the previous grouping of lines had no DIM list open at a physical line boundary."""

    def __init__(self, placed: Sequence[n.PlacedLine], offsets: Sequence[int]) -> None:
        self._placed = placed
        self._offsets = offsets

    def __contains__(self, boundary: object) -> bool:
        assert isinstance(boundary, int)
        before = bisect_left(self._placed, boundary + 1, key=LINE_NUMBER) - 1  # the last logical line starting above
        return before < 0 or _last_physical(self._placed[before], self._offsets) < boundary
