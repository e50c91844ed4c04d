"""A bounded cache for what recent checks used: the per-line caches of the parser, index and analyser.

A language server checks a file on every keystroke for hours; each edit leaves
behind the lines it replaced. Two generations bound the memory without an LRU
list to maintain per lookup: new entries go to the young one, an entry found in
the old one moves to the young one, and when the young one is full it becomes
the old one, dropping whatever no check has asked for since the last turn.

Key policy: a per-line cache is keyed by what the line was parsed from
(``PlacedLine.content``: the parser's one record for its text, dialect, controller
and the macros it names, compared by identity), and what belongs to one place in a
file by that place (line number, statement index). Never by a syntax object, its
``id()`` or its value: every line of the same text shares one, so such a key merges
lines that only look alike.

A batch job that reads many versions of one text (a migration re-reads the program after each
editing pass) keeps them from piling up with ``apart`` and ``keeping_what_it_uses``. Its caches do
not turn over: it prunes them itself, and in a text of more distinct lines than a generation holds a
turn in the middle of a re-read would drop the lines it had yet to read again.
"""

from __future__ import annotations

from collections.abc import Callable, Hashable, Iterable, Iterator
from contextlib import contextmanager
from typing import Generic, TypeVar
from weakref import WeakKeyDictionary, WeakSet

K = TypeVar("K")
V = TypeVar("V")
T = TypeVar("T")

LINES_KEPT = 30_000  # per generation: more than the lines of the largest file a server analyses (25,000)


class RecentCache(Generic[K, V]):
    __slots__ = ("__weakref__", "_old", "_size", "_young", "holds_contents")

    def __init__(self, size: int, *, holds_contents: bool = False) -> None:
        self._size = size  # entries per generation
        self.holds_contents = holds_contents  # its values are lines' ``PlacedLine.content`` (the parser's)
        self._young: dict[K, V] = {}
        self._old: dict[K, V] = {}
        _every_cache.add(self)

    def __len__(self) -> int:
        return len(self._young) + len(self._old)

    def get(self, key: K) -> V | None:
        value = self._young.get(key)
        if value is None:
            value = self._old.pop(key, None)
            if value is not None:
                self.put(key, value)
        return value

    def put(self, key: K, value: V) -> None:
        self._young[key] = value
        if len(self._young) >= self._size and not _batches:
            self._old, self._young = self._young, {}

    def clear(self) -> None:
        self._young.clear()
        self._old.clear()


_every_cache: WeakSet[RecentCache[object, object]] = WeakSet()
_batches = 0  # the ``apart`` blocks open: while there is one, no cache turns over


_Generations = tuple[dict[object, object], dict[object, object]]  # a cache's young and old entries


class Shelf:
    """Per-line caches put aside between ``apart`` blocks: a block given a shelf starts with what
    the last block given it cached, and leaves what it cached there (a migration reads two
    versions of its result as Mint v4, which differ in a few lines)."""

    __slots__ = ("_held",)

    def __init__(self) -> None:
        self._held: WeakKeyDictionary[RecentCache[object, object], _Generations] = WeakKeyDictionary()

    def clear(self) -> None:
        """Drop what the blocks left here: no block given this shelf is to come."""
        self._held.clear()


@contextmanager
def apart(shelf: Shelf | None = None) -> Iterator[None]:
    """Every per-line cache empty for the block (or as ``shelf`` holds it), and back to what it held
    before after it: what the block cached is dropped (a migration's intermediate versions) or put
    on ``shelf``, what others cached is kept. In the block no cache turns over (see above)."""
    global _batches  # noqa: PLW0603 - the one switch ``put`` reads
    held = {cache: (cache._young, cache._old) for cache in list(_every_cache)}
    for cache in held:
        cache._young, cache._old = shelf._held.pop(cache, ({}, {})) if shelf is not None else ({}, {})
    _batches += 1
    try:
        yield
    finally:
        _batches -= 1
        for cache in list(_every_cache):
            if shelf is not None:
                shelf._held[cache] = (cache._young, cache._old)
            cache._young, cache._old = held.get(cache, ({}, {}))


def forget_lines() -> None:
    """Empty every per-line cache: inside ``apart``, the block's own (what it holds apart and on
    shelves is kept), for a batch job with no reading left that they would spare work."""
    for cache in list(_every_cache):
        cache.clear()


def keeping_what_it_uses(action: Callable[[], T], holding: Callable[[T], Iterable[Hashable]] | None = None) -> T:
    """``action()``, a re-read in an ``apart`` block, after which every per-line cache holds what it
    looked up or added, and what it holds about a line whose parse a cache still holds (a key that is
    a value of a cache that ``holds_contents``: a ``PlacedLine.content``); the rest is dropped. The
    index and the findings of a line no edit touched are so kept for the next model and check, which
    the re-read, a parse, never asks for, however many re-reads come first: a migration checks its
    original as Mint v3 and again four re-reads later, and builds a model after three. ``holding``
    names the keys the result holds besides what it looked up: a re-read that takes the lines no edit
    touched over from the earlier reading looks none of them up."""
    used: dict[RecentCache[object, object], dict[object, object]] = {}
    for cache in list(_every_cache):
        cache._old.update(cache._young)
        used[cache] = cache._old  # found there by ``action``, moved back to the young one
        cache._young = {}
    done: list[T] = []
    try:
        done.append(action())
        return done[0]
    finally:
        caches = list(_every_cache)
        held = {content for cache in caches if cache.holds_contents for content in cache._young.values()}
        if holding is not None and done:
            held.update(holding(done[0]))
        for cache in caches:
            old = cache._old
            if old is used.get(cache):
                for key in old.keys() - held:  # the keys kept are most of them after a re-read taking lines over
                    del old[key]
