"""Diagnostics: findings about a source, as values.

Expected problems in user programs are reported as ``Diagnostic`` values, never
raised. Positions are character offsets into the decoded source; ``LineIndex``
turns them into the 1-based lines and columns that users and editors see.
"""

from __future__ import annotations

import re
from array import array
from bisect import bisect_right
from collections.abc import Iterator, Sequence
from dataclasses import field
from enum import StrEnum
from itertools import accumulate, chain
from typing import NamedTuple, overload

from mintlang.records import record

_LINE_BREAK = re.compile(r"\r\n|\r|\n")
_LINE = re.compile(r"[^\r\n]*(?:\r\n|\r|\n)|[^\r\n]+\Z")  # a line with its end; the last may have none


def split_lines(text: str, *, keepends: bool = False) -> list[str]:
    """``str.splitlines`` at the line ends Mint, editors and the LSP know (\\r\\n, \\r, \\n) only.

    Python's also ends a line at a form feed, NEL (\\x85) and a few others, so a listing
    with page breaks would be numbered unlike ``LineIndex`` and every editor.
    """
    lines = _LINE.findall(text)
    return lines if keepends else [line.rstrip("\r\n") for line in lines]


def line_break(text: str) -> str:
    """The line break a line added to ``text`` ends with: its first (\\r\\n, \\r or \\n), as ruff reads a file's,
    so a fix keeps a file's line ends; \\n in a text of one line."""
    found = _LINE_BREAK.search(text)
    return "\n" if found is None else found[0]


def lines_of(text: str) -> Iterator[str]:
    """The lines of ``split_lines(text, keepends=True)`` one at a time, for a reader that may stop
    early or keeps few: the list of a large file's lines is several times its size."""
    return (found.group() for found in _LINE.finditer(text))


_QUOTED_AT_MOST = 40  # characters of source a message quotes whole


def quoted(source: str) -> str:
    """A piece of source as a message names it: whole, or its two ends and its length when it is long
    (a literal of thousands of digits would make a message nobody reads; the code frame shows the place)."""
    if len(source) <= _QUOTED_AT_MOST:
        return source
    end = _QUOTED_AT_MOST // 2
    return f"{source[:end]}…{source[-end:]} ({len(source)} characters)"


class Severity(StrEnum):
    ERROR = "error"
    WARNING = "warning"
    INFO = "info"


class Span(NamedTuple):
    """A half-open range of character offsets ``[start, end)``.

    A named tuple, not a dataclass: every token and node has one, and tuple
    construction is several times cheaper.
    """

    start: int
    end: int

    def shifted(self, offset: int) -> Span:
        return Span(self.start + offset, self.end + offset)


@record
class Edit:
    """Replace the text of ``span`` with ``text``."""

    span: Span
    text: str

    def shifted(self, offset: int) -> Edit:
        return Edit(self.span.shifted(offset), self.text)


def with_edits(text: str, edits: Sequence[Edit]) -> str:
    """``text`` with ``edits``, which do not overlap, made; two insertions at one place in their order, an
    insertion before the text an edit replaces from the same place."""
    for _, edit in sorted(
        enumerate(edits), key=lambda pair: (pair[1].span.start, pair[1].span.end, pair[0]), reverse=True
    ):
        text = text[: edit.span.start] + edit.text + text[edit.span.end :]  # the last first: offsets hold
    return text


@record
class Fix:
    """A named set of edits that resolves a diagnostic.

    ``safe`` says the program means afterwards what it meant (or plainly meant)
    before: ``mint check --fix`` applies it unasked. A guess at the author's
    intent or a change of what runs is unsafe (``--unsafe-fixes``), and so is a
    fix whose rule does not say otherwise.
    """

    title: str
    edits: tuple[Edit, ...]
    safe: bool = False

    def shifted(self, offset: int) -> Fix:
        return Fix(self.title, tuple(edit.shifted(offset) for edit in self.edits), self.safe)

    @classmethod
    def replace(cls, span: Span, text: str) -> Fix:
        """Write ``text`` in place of the word at ``span``: a misspelling's or an old keyword's fix (a guess)."""
        return cls(f"Replace with {text}", (Edit(span, text),))


@record
class Diagnostic:
    """One finding.

    ``code`` is ``E<nnnn>`` for the controller's own error numbers, in four digits
    (``mint_error`` then holds the number) and ``W…``/``I…`` for the toolchain's own checks.
    """

    code: str
    severity: Severity
    span: Span
    message: str
    mint_error: int | None = None
    fixes: tuple[Fix, ...] = field(default=())
    from_v3: bool = False  # about a Mint v3 word left in v4 code: a file mint-migrate would help
    at_run_time: bool = False  # the controller raises it when the line runs, not when it compiles the program

    def shifted(self, offset: int) -> Diagnostic:
        """The same finding ``offset`` characters further on: found in a line, placed in its file."""
        fixes = tuple(fix.shifted(offset) for fix in self.fixes) if self.fixes else ()
        span = self.span
        # Made by position: ``dataclasses.replace`` takes half as long again, and a report of a file of
        # broken lines places tens of thousands of diagnostics as it writes them (``PlacedDiagnostics``).
        return Diagnostic(
            self.code,
            self.severity,
            Span(span.start + offset, span.end + offset),
            self.message,
            self.mint_error,
            fixes,
            self.from_v3,
            self.at_run_time,
        )


@record
class Position:
    line: int  # 1-based
    column: int  # 1-based, in characters


class LinesAndEnd(Sequence[int]):
    """Where the lines of a text start, from where its non-empty physical lines start (a parsed
    document's ``PhysicalLines.offsets``): a text that ends with a line break has one more, empty."""

    __slots__ = ("_end", "_offsets")

    def __init__(self, offsets: Sequence[int], text: str) -> None:
        self._offsets = offsets
        self._end = len(text) if not text or text[-1] in "\r\n" else None

    def __len__(self) -> int:
        return len(self._offsets) + (self._end is not None)

    @overload
    def __getitem__(self, index: int) -> int: ...
    @overload
    def __getitem__(self, index: slice) -> Sequence[int]: ...
    def __getitem__(self, index: int | slice) -> int | Sequence[int]:
        if isinstance(index, slice):
            return [self[at] for at in range(*index.indices(len(self)))]
        if index < 0:
            index += len(self)
        if index == len(self._offsets) and self._end is not None:
            return self._end
        return self._offsets[index]


def line_starts(text: str) -> array[int]:
    """The offset of each line of ``text`` (a line break is ``\r\n``, ``\r`` or ``\n``).

    Without a lone ``\r``, the lengths of the parts between ``\n``s give them at the
    speed of ``str.split``: a language server finds them again for every keystroke.
    """
    if text.count("\r") != text.count("\r\n"):
        return array("q", chain((0,), (match.end() for match in _LINE_BREAK.finditer(text))))
    lengths = map(len, text.split("\n"))
    return array("q", accumulate(map(_PAST_BREAK, lengths), initial=0))[:-1] if text else array("q", (0,))


_PAST_BREAK = (1).__add__  # a line's length with its \n


class LineIndex:
    """Maps offsets to lines and columns; the line starts are found on first use, or given
    (a parsed document knows where its physical lines start).

    Every parse makes one, but a check that finds nothing never needs it.
    """

    __slots__ = ("_length", "_starts_cache", "_text")

    def __init__(self, text: str, starts: Sequence[int] | None = None) -> None:
        self._text = text
        self._length = len(text)
        self._starts_cache = starts

    @property
    def starts(self) -> Sequence[int]:
        """The offset of each line."""
        return self._starts

    @property
    def _starts(self) -> Sequence[int]:
        if self._starts_cache is None:  # machine integers: a tenth of a list of int objects, for a file of short lines
            self._starts_cache = line_starts(self._text)
        return self._starts_cache

    def line_start(self, line: int) -> int:
        """Offset of the first character of 1-based ``line``."""
        return self._starts[line - 1]

    def line_text(self, line: int) -> str:
        """The text of 1-based ``line`` without its line break; empty past the last line."""
        starts = self._starts
        if not 0 < line <= len(starts):
            return ""
        end = starts[line] if line < len(starts) else self._length
        return self._text[starts[line - 1] : end].rstrip("\r\n")

    def position(self, offset: int) -> Position:
        offset = max(0, min(offset, self._length))
        starts = self._starts
        line = bisect_right(starts, offset)
        return Position(line, offset - starts[line - 1] + 1)

    def offset(self, line: int, column: int) -> int:
        """Offset of a 1-based line and column, clamped to the text."""
        starts = self._starts
        line = max(1, min(line, len(starts)))
        return min(starts[line - 1] + column - 1, self._length)
