"""Where a place of one pass's text was in the original, and where it ends up in the migrated text.

The engine applies edits pass after pass, each on the text the last one produced.
A report needs both ends of every item: a change's line in the original and in
the migrated file, a marked line's line in the original (or that the migrator
wrote it). ``History`` keeps each pass's edits, sorted, with where each ends in the
text it produced and how much the edits before it grew the text, so that mapping
an offset through a pass is a bisection instead of a walk over every edit.
"""

from __future__ import annotations

from array import array
from bisect import bisect_left, bisect_right
from dataclasses import field

from mintlang.diagnostics import Span
from mintlang.records import record


@record
class Edit:
    """``text`` in place of ``span`` of one pass's text, asked for by ``rule``."""

    rule: str
    span: Span
    text: str


@record
class _Batch:
    """The edits of one pass, sorted: where each starts and ends in the text before the pass and
    ends in the text it produced, and the growth of the edits before each (one more: all of them).
    Machine integers, not the edits: a run's edits (a marker's text, its span, a Python integer per
    offset) held about twice the program's size until its end, and only these offsets are asked."""

    starts: array[int]
    ends: array[int]
    new_ends: array[int]
    shifts: array[int]

    @classmethod
    def of(cls, edits: list[Edit]) -> _Batch:
        starts, ends, new_ends, shifts = array("q"), array("q"), array("q"), array("q", [0])
        for edit in edits:
            start, end = edit.span
            starts.append(start)
            ends.append(end)
            new_ends.append(start + shifts[-1] + len(edit.text))
            shifts.append(shifts[-1] + len(edit.text) - (end - start))
        return cls(starts, ends, new_ends, shifts)

    def back(self, offset: int, *, at_start: bool) -> tuple[int, bool]:
        """``offset`` of the produced text in the text before the pass, and whether it lies in
        text an edit wrote (then it maps to the start, or end, of what that edit replaced).
        The first character of a replacement stands for the first it replaced."""
        first = bisect_left(self.new_ends, offset)  # the edits before it end before ``offset``
        shift = self.shifts[first]
        starts, ends, new_ends = self.starts, self.ends, self.new_ends
        for index in range(first, len(starts)):  # a slice would copy the rest of a large pass's edits
            start, end, new_end = starts[index], ends[index], new_ends[index]
            new_start = start + shift
            if offset < new_start or (offset == new_start and at_start and start != end):
                break
            if offset < new_end or (offset == new_end and not at_start and offset > new_start):
                return (start if at_start else end), True
            shift += new_end - new_start - (end - start)
        return offset - shift, False

    def forward(self, offset: int) -> int:
        """``offset`` of the text before the pass in the text it produced: after whatever was
        inserted at it, or at the start of the text that replaced it."""
        before = bisect_right(self.starts, offset)  # the edits starting at or before ``offset``
        if before and self.starts[before - 1] <= offset < self.ends[before - 1]:
            return self.starts[before - 1] + self.shifts[before - 1]
        return offset + self.shifts[before]


@record(frozen=False, slots=False)
class History:
    """The passes applied to one file, oldest first."""

    batches: list[_Batch] = field(default_factory=list)

    def record(self, edits: list[Edit]) -> None:
        self.batches.append(_Batch.of(edits))

    def to_source(self, span: Span) -> Span:
        """``span`` of the current text in the original: offsets outside earlier edits shift by
        their growth; an offset inside text an earlier edit wrote maps to what it replaced."""
        start, end = span
        for batch in reversed(self.batches):
            start, _ = batch.back(start, at_start=True)
            end = start if span.start == span.end else batch.back(end, at_start=False)[0]
        return Span(start, max(start, end))

    def origin(self, offset: int) -> int | None:
        """``offset`` of the current text in the original, or None when the migrator wrote it."""
        for batch in reversed(self.batches):
            offset, written = batch.back(offset, at_start=True)
            if written:
                return None
        return offset

    def forward(self, offset: int, after: int) -> int:
        """``offset`` of the text the first ``after`` passes produced, in the current text."""
        for batch in self.batches[after:]:
            offset = batch.forward(offset)
        return offset
