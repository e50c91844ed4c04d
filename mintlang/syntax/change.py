"""Where an edit changed a document, and where everything else moved to.

A re-parse (``mintlang.syntax.reparse``) reads again only the whole logical lines
around an edit: the *window*, from ``start`` to ``old_end`` in the previous text and
to ``new_end`` in the new one. Text before the window did not move; text after it
moved by ``shift`` characters. What was found outside the window (a diagnostic, a
fix) is carried over by mapping its offsets; what touches the inside of the window
cannot be, and is found again.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import replace
from typing import Protocol, Self, TypeVar

from mintlang.diagnostics import Diagnostic, Edit, Fix, Span
from mintlang.records import record


class _Placed(Protocol):
    """Something found at a place in a file: a diagnostic, a macro's use."""

    @property
    def span(self) -> Span: ...

    def shifted(self, offset: int) -> Self: ...


P = TypeVar("P", bound=_Placed)


@record
class Window:
    """Whole physical lines that an edit replaced."""

    start: int  # where the window starts, in both texts: a physical line's start
    old_end: int  # where it ended in the previous text: a physical line's start, or the end
    new_end: int  # where it ends in the new text
    previous_length: int  # of the previous text

    @property
    def shift(self) -> int:
        return self.new_end - self.old_end

    @property
    def reaches_end(self) -> bool:
        """The window runs to the end of the text: what depends on how the file ends may have changed."""
        return self.old_end == self.previous_length

    def _start(self, offset: int) -> int | None:
        if offset < self.start:
            return offset
        return offset + self.shift if offset >= self.old_end else None

    def _end(self, offset: int) -> int | None:
        """Where a span ending at ``offset`` ends now. A span that ends where the window does took in
        its last line break, and what it covers was decided by the text before it: found again."""
        if offset <= self.start:
            return offset
        return offset + self.shift if offset > self.old_end else None

    def span(self, span: Span) -> Span | None:
        """Where ``span`` of the previous text is now; None where it reaches into the window."""
        start = self._start(span.start)
        end = start if span.end == span.start else self._end(span.end)
        if start is None or end is None:
            return None
        return span if start == span.start and end == span.end else Span(start, end)

    def diagnostic(self, diagnostic: Diagnostic) -> Diagnostic | None:
        """``diagnostic`` of the previous text, with its fixes, placed in the new one; None where any of
        its offsets lies in the window (the text there changed, so it must be found again)."""
        span = self.span(diagnostic.span)
        if span is None:
            return None
        fixes: list[Fix] = []
        for fix in diagnostic.fixes:
            edits: list[Edit] = []
            for edit in fix.edits:
                moved = self.span(edit.span)
                if moved is None:
                    return None
                edits.append(edit if moved is edit.span else Edit(moved, edit.text))
            fixes.append(replace(fix, edits=tuple(edits)))
        if span is diagnostic.span and not self.shift:
            return diagnostic
        return replace(diagnostic, span=span, fixes=tuple(fixes))

    def spliced(self, previous: Iterable[P], found: Iterable[P]) -> tuple[P, ...]:
        """What was found before the window, then ``found`` (in it), then what was found after it,
        moved. At the end of the text, what was found where the window ends (past a last line
        without a line break) was found in the window."""
        start, end, shift = self.start, self.old_end, self.shift
        before = [item for item in previous if item.span.start < start]
        if self.reaches_end:
            return (*before, *found)
        after = (item if not shift else item.shifted(shift) for item in previous if item.span.start >= end)
        return (*before, *found, *after)


@record
class Change(Window):
    """The window of whole logical lines a re-parse read again."""

    first_line: int  # the index in ``Document.placed`` of the window's first logical line
    old_lines: int  # how many logical lines the window held
    new_lines: int  # how many it holds now
    line_shift: int  # physical lines added (fewer than none: removed)
