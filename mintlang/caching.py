"""A bounded cache for what recent checks used: the per-line caches of the parser, index and analyser.

A language server checks a file on every keystroke for hours; each edit leaves
behind the lines it replaced. Two generations bound the memory without an LRU
list to maintain per lookup: new entries go to the young one, an entry found in
the old one moves to the young one, and when the young one is full it becomes
the old one, dropping whatever no check has asked for since the last turn.

Key policy: a per-line cache is keyed by what the line was parsed from
(``PlacedLine.content``: its text, dialect, controller and the macros it names),
and what belongs to one place in a file by that place (line number, statement
index). Never by a syntax object, its ``id()`` or its value: every line of the
same text shares one, so such a key merges lines that only look alike.

A batch job that reads many versions of one text (a migration re-reads the program after each
editing pass) keeps them from piling up with ``apart`` and ``keeping_what_it_uses``.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Generic, TypeVar
from weakref import WeakSet

K = TypeVar("K")
V = TypeVar("V")
T = TypeVar("T")

LINES_KEPT = 30_000  # per generation: more than the lines of the largest file a server analyses (25,000)


class RecentCache(Generic[K, V]):
    __slots__ = ("__weakref__", "_old", "_size", "_young")

    def __init__(self, size: int) -> None:
        self._size = size  # entries per generation
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
        if len(self._young) >= self._size:
            self._old, self._young = self._young, {}

    def clear(self) -> None:
        self._young.clear()
        self._old.clear()


_every_cache: WeakSet[RecentCache[object, object]] = WeakSet()


@contextmanager
def apart() -> Iterator[None]:
    """Every per-line cache empty for the block, and back to what it held before after it: what the
    block cached is dropped (a migration's intermediate versions), what others cached is kept."""
    held = {cache: (cache._young, cache._old) for cache in list(_every_cache)}
    for cache in held:
        cache._young, cache._old = {}, {}
    try:
        yield
    finally:
        for cache in list(_every_cache):
            cache._young, cache._old = held.get(cache, ({}, {}))


def keeping_what_it_uses(action: Callable[[], T]) -> T:
    """``action()``, after which every per-line cache holds only what it looked up or added."""
    for cache in list(_every_cache):
        cache._old, cache._young = cache._young, {}
    try:
        return action()
    finally:
        for cache in list(_every_cache):
            cache._old = {}
