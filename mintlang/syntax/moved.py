"""The lines of a re-parsed document: earlier versions' lines, moved by the edits since.

An edit moves every line below it; making each of them again at its new offset
costs time in proportion to the file on every keystroke. ``Moved`` keeps slices
of earlier versions' sequences instead, each with how far its items moved, and
moves an item when it is read. The first full iteration moves them all, once,
and keeps them. A language server typing in one place keeps three pieces
(above, the edited lines, below); edits in many places add pieces, and past
``_MOST_PIECES`` the items are moved into one sequence again. ``MovedLines``
holds a document's logical lines, ``MovedOffsets`` where its physical lines start, ``Spliced``
what is kept per line without a place (the line index).
"""

from __future__ import annotations

from array import array
from bisect import bisect_left as _bisect_left
from bisect import bisect_right as _bisect_right
from collections.abc import Callable, Iterable, Iterator, Sequence
from itertools import accumulate, chain, islice, repeat
from operator import itemgetter
from typing import Any, Generic, TypeVar, overload

from mintlang.records import record
from mintlang.syntax.nodes import PlacedLine
from mintlang.syntax.packed import equal_items

_MOST_PIECES = 16
T = TypeVar("T")
_new = tuple.__new__
_ORIGIN, _NUMBER, _SYNTAX, _CONTENT = map(itemgetter, range(4))  # a ``PlacedLine``'s fields
LINE_NUMBER = _NUMBER  # the key that finds a logical line by its number (``bisect_left(lines, n, key=LINE_NUMBER)``)
Search = Callable[..., int]  # ``bisect.bisect_left`` or ``bisect.bisect_right``


@record
class _Piece(Generic[T]):
    """``items[start:end]`` of some version, moved ``shift`` characters and ``line_shift`` lines since."""

    items: Sequence[T]
    start: int
    end: int
    shift: int
    line_shift: int

    @property
    def still(self) -> bool:
        return not (self.shift or self.line_shift)


class Moved(Sequence[T]):
    """Pieces of earlier sequences, each moved (the base of the two kinds below)."""

    __slots__ = ("_ends", "_flat", "_pieces")

    def __init__(self, pieces: Sequence[_Piece[T]]) -> None:
        self._pieces = tuple(piece for piece in pieces if piece.end > piece.start)
        self._ends = list(accumulate(piece.end - piece.start for piece in self._pieces))
        self._flat: Sequence[T] | None = None

    @staticmethod
    def moved(items: Iterable[T], shift: int, line_shift: int) -> Iterator[T]:
        """Each of ``items`` ``shift`` characters and ``line_shift`` lines further on: a whole
        piece at a time, as a file's lines below an edit are moved on every keystroke."""
        raise NotImplementedError

    @staticmethod
    def flat(items: Iterable[T]) -> Sequence[T]:
        """The items as one sequence of their own."""
        return tuple(items)

    @classmethod
    def spliced(
        cls,
        items: Sequence[T],
        replaced: tuple[int, int],
        replacement: Sequence[T],
        shift: int,
        line_shift: int,
    ) -> Sequence[T]:
        """``items`` with ``replaced`` (first and end index) replaced by ``replacement``, those after moved."""
        first, end = replaced
        pieces = [*_pieces(items, 0, first, 0, 0), _Piece(replacement, 0, len(replacement), 0, 0)]
        pieces += _pieces(items, end, len(items), shift, line_shift)
        if len(pieces) > _MOST_PIECES:
            return cls.flat(chain.from_iterable(cls._items(piece) for piece in pieces))
        return cls(pieces)

    @classmethod
    def _items(cls, piece: _Piece[T]) -> Iterator[T]:
        items = islice(piece.items, piece.start, piece.end)
        return items if piece.still else cls.moved(items, piece.shift, piece.line_shift)

    def __len__(self) -> int:
        return self._ends[-1] if self._ends else 0

    @overload
    def __getitem__(self, index: int) -> T: ...
    @overload
    def __getitem__(self, index: slice) -> Sequence[T]: ...
    def __getitem__(self, index: int | slice) -> T | Sequence[T]:
        if self._flat is not None:
            return self._flat[index]
        if isinstance(index, slice):
            start, stop, step = index.indices(len(self))
            if step != 1:
                return self.flat(self)[index]
            return self.flat(chain.from_iterable(map(self._items, _pieces(self, start, stop, 0, 0))))
        if index < 0:
            index += len(self)
        if not 0 <= index < len(self):
            raise IndexError("index out of range")
        at = _bisect_right(self._ends, index)
        piece = self._pieces[at]
        item = piece.items[piece.start + index - (self._ends[at - 1] if at else 0)]
        return item if piece.still else next(self.moved((item,), piece.shift, piece.line_shift))

    def bisect(self, value: Any, key: Callable[[T], Any] | None, search: Search) -> int:
        """``search`` for ``value`` piece by piece, each in C on the piece's own items: through
        ``__getitem__`` every probe would be a call in Python."""
        if self._flat is not None:
            return search(self._flat, value, key=key)
        base = 0
        for piece, end in zip(self._pieces, self._ends, strict=True):
            unmoved = self._unmoved(value, key, piece)
            if unmoved is None:  # a key these items cannot be searched by before they move
                return search(self, value, key=key)
            found = search(piece.items, unmoved, piece.start, piece.end, key=key)
            if found < piece.end:
                return base + found - piece.start
            base = end
        return base

    @staticmethod
    def _unmoved(value: Any, key: Callable[[T], Any] | None, piece: _Piece[T]) -> Any:
        """What ``value`` was among ``piece``'s items before they moved; None when ``key`` does not say."""
        return None

    def __iter__(self) -> Iterator[T]:
        if self._flat is None:
            self._flat = self.flat(chain.from_iterable(map(self._items, self._pieces)))
            self._pieces = (_Piece(self._flat, 0, len(self._flat), 0, 0),)  # earlier versions' sequences may go
        return iter(self._flat)

    def __eq__(self, other: object) -> bool:
        return equal_items(self, other)

    __hash__ = None  # type: ignore[assignment] - equal to a tuple of the same items, which hashes

    def __repr__(self) -> str:
        return f"{type(self).__name__}({len(self)} in {len(self._pieces)} pieces)"


class MovedLines(Moved[PlacedLine]):
    """A document's logical lines (``Document.placed``).

    Flat, they are a tuple of ``PlacedLine``: a re-parsed document is the language server's,
    which passes over its lines on every keystroke, and packing them into columns again
    (``PackedLines``) would make every line anew for each pass.
    """

    __slots__ = ()

    @staticmethod
    def moved(items: Iterable[PlacedLine], shift: int, line_shift: int) -> Iterator[PlacedLine]:
        # Column by column in C: a named tuple's constructor is a Python function, called per line.
        lines = list(items)
        origins = map(shift.__add__, map(_ORIGIN, lines))
        numbers = map(line_shift.__add__, map(_NUMBER, lines))
        fields = zip(origins, numbers, map(_SYNTAX, lines), map(_CONTENT, lines), strict=True)
        return map(_new, repeat(PlacedLine), fields)

    @staticmethod
    def _unmoved(value: Any, key: Callable[[PlacedLine], Any] | None, piece: _Piece[PlacedLine]) -> Any:
        return value - piece.line_shift if key is _NUMBER else None


class MovedOffsets(Moved[int]):
    """Where a document's physical lines start (``PhysicalLines.offsets``): machine integers once flat."""

    __slots__ = ()

    @staticmethod
    def moved(items: Iterable[int], shift: int, line_shift: int) -> Iterator[int]:
        return map(shift.__add__, items)

    @staticmethod
    def _unmoved(value: Any, key: Callable[[int], Any] | None, piece: _Piece[int]) -> Any:
        return value - piece.shift if key is None else None

    @staticmethod
    def flat(items: Iterable[int]) -> Sequence[int]:
        return array("q", items)


class Spliced(Moved[T]):
    """Items that name no place (each line's index), spliced around an edit: nothing in them moves, and a
    keystroke that reads none of them (typing in a comment) copies none."""

    __slots__ = ()

    @staticmethod
    def moved(items: Iterable[T], shift: int, line_shift: int) -> Iterator[T]:
        return iter(items)


def bisect_left(items: Sequence[T], value: Any, key: Callable[[T], Any] | None = None) -> int:
    """``bisect.bisect_left``, in C on each piece of a ``Moved``."""
    return items.bisect(value, key, _bisect_left) if isinstance(items, Moved) else _bisect_left(items, value, key=key)


def bisect_right(items: Sequence[T], value: Any, key: Callable[[T], Any] | None = None) -> int:
    """``bisect.bisect_right``, in C on each piece of a ``Moved``."""
    return items.bisect(value, key, _bisect_right) if isinstance(items, Moved) else _bisect_right(items, value, key=key)


def _pieces(items: Sequence[T], start: int, end: int, shift: int, line_shift: int) -> list[_Piece[T]]:
    """The pieces that hold ``items[start:end]``, moved ``shift`` characters and ``line_shift`` lines more."""
    if start >= end:
        return []
    if not isinstance(items, Moved):
        return [_Piece(items, start, end, shift, line_shift)]
    if items._flat is not None:
        return [_Piece(items._flat, start, end, shift, line_shift)]
    found: list[_Piece[T]] = []
    offset = 0
    for piece in items._pieces:
        size = piece.end - piece.start
        low, high = max(start, offset), min(end, offset + size)
        if low < high:
            found.append(
                _Piece(
                    piece.items,
                    piece.start + low - offset,
                    piece.start + high - offset,
                    piece.shift + shift,
                    piece.line_shift + line_shift,
                )
            )
        offset += size
    return found
