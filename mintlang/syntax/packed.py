"""A document's logical lines and its parser's findings kept as columns, each item made when read.

A ``PlacedLine`` per line, with its offset and line number as two integer objects,
took about a tenth of a check's memory on a file of short distinct lines. The
offsets and numbers here are machine integers in two arrays, the syntax and the
cache keys two tuples whose items the parser shares between equal lines; a pass
over the lines makes each named tuple as it goes, in C, and drops it after.
"""

from __future__ import annotations

from array import array
from collections.abc import Hashable, Iterable, Iterator, Sequence
from functools import partial
from typing import overload

from mintlang.diagnostics import Diagnostic
from mintlang.syntax.nodes import LineSyntax, PlacedLine

_placed = partial(tuple.__new__, PlacedLine)  # a PlacedLine from its four fields, without the Python constructor


def equal_items(mine: Sequence[object], other: object) -> bool:
    """Whether ``other`` is a sequence of the same items: a lazy sequence equals the tuple of its items."""
    if not isinstance(other, Sequence):
        return NotImplemented
    return len(mine) == len(other) and all(a == b for a, b in zip(mine, other, strict=True))


class PackedLines(Sequence[PlacedLine]):
    """Logical lines in file order: ``PlacedLine`` items, stored field by field."""

    __slots__ = ("_contents", "_numbers", "_origins", "_syntaxes")

    def __init__(
        self,
        origins: array[int],
        numbers: array[int],
        syntaxes: tuple[LineSyntax, ...],
        contents: tuple[Hashable, ...],
    ) -> None:
        self._origins = origins
        self._numbers = numbers
        self._syntaxes = syntaxes
        self._contents = contents

    def columns(self) -> tuple[array[int], array[int], tuple[LineSyntax, ...], tuple[Hashable, ...]]:
        """The lines' origins, numbers, syntaxes and contents: for a reader that takes most of them over
        into another document (``mintlang.syntax.reread``) without making a line of each."""
        return self._origins, self._numbers, self._syntaxes, self._contents

    def __len__(self) -> int:
        return len(self._syntaxes)

    @overload
    def __getitem__(self, index: int) -> PlacedLine: ...
    @overload
    def __getitem__(self, index: slice) -> Sequence[PlacedLine]: ...
    def __getitem__(self, index: int | slice) -> PlacedLine | Sequence[PlacedLine]:
        if isinstance(index, slice):
            return PackedLines(self._origins[index], self._numbers[index], self._syntaxes[index], self._contents[index])
        return _placed((self._origins[index], self._numbers[index], self._syntaxes[index], self._contents[index]))

    def __iter__(self) -> Iterator[PlacedLine]:
        return map(_placed, zip(self._origins, self._numbers, self._syntaxes, self._contents, strict=True))

    def __eq__(self, other: object) -> bool:
        return equal_items(self, other)

    __hash__ = None  # type: ignore[assignment] - equal to a tuple of the same lines, which hashes

    def __repr__(self) -> str:
        return f"PackedLines({len(self)} lines)"


class PlacedDiagnostics(Sequence[Diagnostic]):
    """Diagnostics found at a line's own offsets, each with the offset of its line: shifted when read.

    A file of broken lines has a finding on every line; shifted and kept, each was a
    ``Diagnostic``, a ``Span`` and two integers, the largest part of a check's memory.
    Here each is a reference to the finding its line's text shares and a machine integer.
    """

    __slots__ = ("_found", "_origins")

    def __init__(self, found: tuple[Diagnostic, ...], origins: array[int]) -> None:
        self._found = found
        self._origins = origins

    @classmethod
    def placed(cls, diagnostics: Iterable[Diagnostic]) -> PlacedDiagnostics:
        """Diagnostics already at their offsets in the file."""
        found = tuple(diagnostics)
        return cls(found, array("q", bytes(8 * len(found))))

    def pairs(self) -> Iterator[tuple[Diagnostic, int]]:
        """Each diagnostic as found, with the offset that places it."""
        return zip(self._found, self._origins, strict=True)

    def __len__(self) -> int:
        return len(self._found)

    @overload
    def __getitem__(self, index: int) -> Diagnostic: ...
    @overload
    def __getitem__(self, index: slice) -> Sequence[Diagnostic]: ...
    def __getitem__(self, index: int | slice) -> Diagnostic | Sequence[Diagnostic]:
        if isinstance(index, slice):
            return PlacedDiagnostics(self._found[index], self._origins[index])
        return _shifted(self._found[index], self._origins[index])

    def __iter__(self) -> Iterator[Diagnostic]:
        return map(_shifted, self._found, self._origins)

    def __eq__(self, other: object) -> bool:
        return equal_items(self, other)

    __hash__ = None  # type: ignore[assignment] - equal to a tuple of the same diagnostics, which hashes

    def __repr__(self) -> str:
        return f"PlacedDiagnostics({len(self)} diagnostics)"


def _shifted(diagnostic: Diagnostic, origin: int) -> Diagnostic:
    return diagnostic.shifted(origin) if origin else diagnostic
