"""Reading a document again after edits in many places: only the lines they touched.

A migration pass rewrites a program in hundreds of places, then reads it again. Reading every
line again costs half a parse even when each line comes from the per-line caches (``reparse``
reads again the lines of one edit only, as a keystroke makes). Here each edit's physical lines
are lexed again and the logical lines around them grouped and parsed again, and every other
line is taken over from the previous document, moved by the edits above it, a file's columns
at a time. The result equals ``parse`` of the new text (a property test holds it to that).
Where the previous reading found something to report (the lexer's or the parser's issues),
defined or used a macro, or where a DIM list continued over lines reaches from one edit to
the next, it is None, and the caller parses the text afresh.
"""

from __future__ import annotations

from array import array
from bisect import bisect_left, bisect_right
from collections.abc import Sequence
from operator import itemgetter

from mintlang.diagnostics import Diagnostic, LineIndex, LinesAndEnd
from mintlang.records import record
from mintlang.syntax.lexer import LexedLine, PhysicalLines, TokenStream, lex_lines
from mintlang.syntax.lines import LineGroup, groups_from
from mintlang.syntax.packed import PackedLines, PlacedDiagnostics
from mintlang.syntax.parser import Document, PlacedLines
from mintlang.syntax.tokens import TokenKind

Replaced = tuple[int, int, int]  # an edit: ``start:end`` of the previous text replaced by so many characters
_LEXED = itemgetter(1)


@record(frozen=False)
class _Window:
    """Physical lines ``first`` to ``stop`` of the previous text, which edits changed: how far the edits
    above moved them (``shift``), how much those in it changed its length (``grown``), and what
    they became: ``lines`` at ``offsets``."""

    first: int
    stop: int
    shift: int
    grown: int
    offsets: array[int]
    lines: list[LexedLine]


def reread(previous: Document, source: str, edits: Sequence[Replaced]) -> Document | None:
    """``parse`` of ``source`` as ``previous`` was read (dialect, controller, macros), ``source`` being
    ``previous.source`` with ``edits`` made (in order, none overlapping); None where it must be parsed."""
    placed = previous.placed
    if (
        previous.lexer_issues
        or previous.parse_issues
        or previous.macros
        or previous.expansions
        or not isinstance(placed, PackedLines)
    ):
        return None
    windows = _windows(previous, source, edits)
    if windows is None:
        return None
    return _Reread(previous, source, placed, windows).document()


def _windows(previous: Document, source: str, edits: Sequence[Replaced]) -> list[_Window] | None:
    """The physical lines the edits changed, lexed again: whole lines, the one above an edit at a line's
    start included (a ``\\r`` ending it may meet an inserted ``\\n``); windows that meet are one."""
    offsets, old = previous.physical.offsets, previous.source
    count = len(offsets)
    spans: list[list[int]] = []  # first line, stop line, length change
    for start, end, length in edits:
        first = max(bisect_right(offsets, start) - 1, 0)
        if first and offsets[first] == start:
            first -= 1
        stop = min(max(bisect_right(offsets, end), first + 1), count)
        grown = length - (end - start)
        if spans and first <= spans[-1][1]:
            spans[-1][1] = max(spans[-1][1], stop)
            spans[-1][2] += grown
        else:
            spans.append([first, stop, grown])
    windows: list[_Window] = []
    shift = 0
    for first, stop, grown in spans:
        start = offsets[first] if first < count else len(old)
        end = offsets[stop] if stop < count else len(old)
        lexed_offsets: array[int] = array("q")
        lines: list[LexedLine] = []
        issues: list[Diagnostic] = []
        lex_lines(
            source[start + shift : end + shift + grown], previous.dialect, start + shift, lexed_offsets, lines, issues
        )
        if issues:
            return None
        windows.append(_Window(first, stop, shift, grown, lexed_offsets, lines))
        shift += grown
    return windows


class _Reread:
    def __init__(self, previous: Document, source: str, placed: PackedLines, windows: list[_Window]) -> None:
        self.previous = previous
        self.source = source
        self.windows = windows
        self.old_offsets = previous.physical.offsets
        self.origins, self.numbers, self.syntaxes, self.contents = placed.columns()

    def document(self) -> Document | None:
        previous = self.previous
        physical, starts = self._physical()
        origins: array[int] = array("q")
        numbers: array[int] = array("q")
        syntaxes: list[object] = []
        contents: list[object] = []
        taken = 0  # the previous document's logical lines taken over or replaced so far
        line_shift = 0  # how many physical lines the windows above added
        replaced: list[tuple[int, int]] = []  # per window, the previous document's logical lines it replaces
        groups: list[LineGroup] = []
        ends: list[int] = []  # per window, where its logical lines end among ``groups``
        for index, start in enumerate(starts):
            regrouped = self._regroup(physical, index, start, line_shift, taken)
            if regrouped is None:
                return None
            first_line, taken, window_groups = regrouped
            replaced.append((first_line, taken))
            groups += window_groups
            ends.append(len(groups))
            window = self.windows[index]
            line_shift += len(window.lines) - (window.stop - window.first)
        parsed = PlacedLines({})
        parsed.parse(groups, previous.context)  # at once: a call for each of a pass's edits cost more than they
        if parsed.found or parsed.definitions or parsed.expansions:
            return None
        taken = line_shift = made = 0
        for window, (first_line, end_line), end in zip(self.windows, replaced, ends, strict=True):
            self._take(origins, numbers, syntaxes, contents, (taken, first_line), window.shift, line_shift)
            origins += parsed.origins[made:end]
            numbers += parsed.numbers[made:end]
            syntaxes += parsed.syntaxes[made:end]
            contents += parsed.contents[made:end]
            taken, made = end_line, end
            line_shift += len(window.lines) - (window.stop - window.first)
        last = self.windows[-1] if self.windows else None
        shift = last.shift + last.grown if last is not None else 0
        self._take(origins, numbers, syntaxes, contents, (taken, len(self.syntaxes)), shift, line_shift)
        source = self.source
        return Document(
            source,
            previous.dialect,
            TokenStream(physical),
            physical,
            PackedLines(origins, numbers, tuple(syntaxes), tuple(contents)),  # type: ignore[arg-type]
            (),
            PlacedDiagnostics((), array("q")),
            {},
            (),
            (),
            LineIndex(source, LinesAndEnd(physical.offsets, source)),
            previous.context,
        )

    def _physical(self) -> tuple[PhysicalLines, list[int]]:
        """The new text's physical lines, and where each window's lines start among them."""
        old_offsets = self.old_offsets
        old_lines = list(map(_LEXED, self.previous.physical))
        offsets: array[int] = array("q")
        lines: list[LexedLine] = []
        starts: list[int] = []
        taken = shift = 0
        for window in self.windows:
            kept = old_offsets[taken : window.first]
            offsets.extend(map(shift.__add__, kept) if shift else kept)
            lines += old_lines[taken : window.first]
            starts.append(len(lines))
            offsets += window.offsets
            lines += window.lines
            taken, shift = window.stop, shift + window.grown
        kept = old_offsets[taken:]
        offsets.extend(map(shift.__add__, kept) if shift else kept)
        lines += old_lines[taken:]
        return PhysicalLines(offsets, tuple(lines)), starts

    def _regroup(
        self, physical: PhysicalLines, index: int, start: int, line_shift: int, taken: int
    ) -> tuple[int, int, list[LineGroup]] | None:
        """The previous document's logical lines that window ``index`` (its lines from ``start`` among the new
        physical lines) replaces, as first and end index, and the new logical lines grouped in their
        place: from the one that reaches into the window until the grouping meets the previous one
        below it. None where that reaches into logical lines an earlier window replaced, or into the
        next window."""
        window, numbers = self.windows[index], self.numbers
        first_line = bisect_left(numbers, window.first + 1)  # the first logical line starting in the window
        if first_line and self._runs_into(first_line - 1, window.first):
            first_line -= 1  # a DIM list continued over the window's first line, or waiting to be
        restart = numbers[first_line] - 1 if first_line < len(numbers) else len(self.old_offsets)
        restart = min(restart, window.first)
        if first_line < taken:
            return None
        grown_lines = len(window.lines) - (window.stop - window.first)
        past = start + len(window.lines)
        groups: list[LineGroup] = []
        resume = len(self.old_offsets)
        for group, after in groups_from(physical, restart + line_shift):
            groups.append(group)
            if after >= past and self._group_ends_at(after - line_shift - grown_lines):
                resume = after - line_shift - grown_lines
                break
        if index + 1 < len(self.windows) and resume > self.windows[index + 1].first:
            return None
        return first_line, bisect_left(numbers, resume + 1), groups

    def _last_physical(self, line: int) -> int:
        """The index of the last physical line of the previous document's logical line ``line``."""
        end = self.origins[line] + max(self.syntaxes[line].span.end - 1, 0)
        return bisect_right(self.old_offsets, end) - 1

    def _runs_into(self, line: int, first: int) -> bool:
        """Logical line ``line`` (above physical line ``first``) reaches it, or ends in a comma a DIM list
        would continue after: the edit may change where it ends."""
        last = self._last_physical(line)
        kinds = self.previous.physical.lexed(last).kinds
        return last >= first or (bool(kinds) and kinds[-1] is TokenKind.COMMA)

    def _group_ends_at(self, boundary: int) -> bool:
        """Whether the previous grouping had no DIM list open at physical line ``boundary``."""
        before = bisect_left(self.numbers, boundary + 1) - 1  # the last logical line starting above
        return before < 0 or self._last_physical(before) < boundary

    def _take(  # noqa: PLR0917 - the four columns, the range and the two shifts
        self,
        origins: array[int],
        numbers: array[int],
        syntaxes: list[object],
        contents: list[object],
        lines: tuple[int, int],
        shift: int,
        line_shift: int,
    ) -> None:
        """The previous document's logical lines ``lines`` (first and end index), moved ``shift`` characters
        and ``line_shift`` lines."""
        first, end = lines
        kept = self.origins[first:end]
        origins.extend(map(shift.__add__, kept) if shift else kept)
        kept = self.numbers[first:end]
        numbers.extend(map(line_shift.__add__, kept) if line_shift else kept)
        syntaxes += self.syntaxes[first:end]
        contents += self.contents[first:end]
