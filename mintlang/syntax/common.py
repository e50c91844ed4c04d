"""What two versions of a text share at their start and at their end.

Found by comparing whole slices: strings compare at the speed of memory, so
finding where a keystroke changed a file of a megabyte takes a few comparisons,
not a loop over its characters. Where part of the answer is known — the editor
said which range it replaced (``edited``) — the search starts from there in
doubling steps, so it costs the distance to the first difference, not the file.
The language server asks for the same two versions more than once per keystroke
(the dialect's detection, the re-parse), so the latest answers are remembered.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import NamedTuple

_FIRST_STEP = 64  # characters compared first from what is known shared; each step after compares twice as many
_MOST_PAIRS = 4  # an editor may send several changes before an analysis asks; each pair keeps its texts alive


class _Pair(NamedTuple):
    """Two texts, kept alive so that identity names them, with ``start`` and ``end`` characters known shared
    at each end: all there are when ``exact``, else as many as the editor's changes tell."""

    old: str
    new: str
    start: int
    end: int
    exact: bool


# The latest first, replaced whole, so that a reader on another thread sees one list or the other.
_pairs: tuple[_Pair, ...] = ()


def shared_ends(old: str, new: str) -> tuple[int, int]:
    """How many characters ``old`` and ``new`` share at the start, then at the end after that start."""
    for pair in _pairs:
        if pair.old is old and pair.new is new:
            return (pair.start, pair.end) if pair.exact else _remember(old, new, pair.start, pair.end)
    return _remember(old, new, 0, 0)


def edited(old: str, new: str, start: int, end: int) -> None:
    """Remember that ``new`` is ``old`` with ``old[start:end]`` replaced, as an editor's change says, so that
    ``shared_ends`` of the two, or of a version before ``old`` and ``new``, need not compare the files."""
    shared_at_end = len(old) - end
    through = (  # what a version before ``old`` shares with ``new``: what it shared with ``old``, and the change kept
        _Pair(pair.old, new, min(pair.start, start), min(pair.end, shared_at_end), False)
        for pair in _pairs
        if pair.new is old and pair.old is not old
    )
    _keep((_Pair(old, new, start, shared_at_end, False), *through))


def _remember(old: str, new: str, known_start: int, known_end: int) -> tuple[int, int]:
    start = _common_prefix(old, new, known_start)
    most = min(len(old), len(new)) - start
    ends = (start, _common_suffix(old, new, min(known_end, most), most))
    others = (pair for pair in _pairs if not (pair.old is old and pair.new is new))
    _keep((_Pair(old, new, *ends, True), *others))
    return ends


def _keep(pairs: tuple[_Pair, ...]) -> None:
    global _pairs  # noqa: PLW0603 - the module's own memory of the latest pairs
    _pairs = pairs[:_MOST_PAIRS]


def _common_prefix(old: str, new: str, low: int) -> int:
    """How many characters ``old`` and ``new`` share at the start, ``low`` of them known shared."""
    return _extent(lambda low, middle: new.startswith(old[low:middle], low), low, min(len(old), len(new)))


def _common_suffix(old: str, new: str, low: int, most: int) -> int:
    """How many characters (at most ``most``) ``old`` and ``new`` share at the end, ``low`` of them known shared."""
    old_length, new_length = len(old), len(new)
    return _extent(
        lambda low, middle: new.endswith(old[old_length - middle : old_length - low], 0, new_length - low), low, most
    )


def _extent(shared: Callable[[int, int], bool], low: int, high: int) -> int:
    """The most characters, ``low`` to ``high``, shared from the first on: ``shared(low, middle)`` says whether
    those from ``low`` up to ``middle`` are, and is asked of doubling stretches, then of halves."""
    step = _FIRST_STEP
    while low < high:
        middle = min(low + step, high)
        if not shared(low, middle):
            high = middle - 1
            break
        low, step = middle, step * 2
    while low < high:
        middle = (low + high + 1) // 2
        if shared(low, middle):
            low = middle
        else:
            high = middle - 1
    return low
