"""The per-line caches keep what recent checks used and forget the rest, within a bound."""

from __future__ import annotations

from mintlang.caching import RecentCache


def test_an_entry_asked_for_since_the_last_turn_survives_the_next() -> None:
    cache: RecentCache[str, int] = RecentCache(size=3)
    cache.put("kept", 1)
    cache.put("dropped", 2)
    cache.put("third", 3)  # the young generation is full: it becomes the old one
    assert cache.get("kept") == 1  # moves back to the young one
    for key in ("a", "b", "c"):  # fills the young one again: the old one, with "dropped", is let go
        cache.put(key, 0)
    assert cache.get("kept") == 1
    assert cache.get("dropped") is None


def test_it_never_holds_more_than_two_generations() -> None:
    cache: RecentCache[int, int] = RecentCache(size=100)
    for key in range(10_000):
        cache.put(key, key)
    assert len(cache) <= 200
    assert cache.get(9_999) == 9_999
