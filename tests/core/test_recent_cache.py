"""The per-line caches keep what recent checks used and forget the rest, within a bound."""

from __future__ import annotations

from mintlang.caching import RecentCache, Shelf, apart, forget_lines, keeping_what_it_uses


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


def test_a_block_apart_starts_empty_and_leaves_what_was_there_before() -> None:
    cache: RecentCache[str, int] = RecentCache(size=100)
    cache.put("before", 1)
    with apart():
        assert cache.get("before") is None
        cache.put("during", 2)
        assert cache.get("during") == 2
    assert cache.get("before") == 1
    assert cache.get("during") is None


def test_a_cache_made_apart_is_empty_after_the_block() -> None:
    with apart():
        cache: RecentCache[str, int] = RecentCache(size=100)
        cache.put("during", 2)
    assert len(cache) == 0


def test_a_block_given_a_shelf_starts_with_what_the_last_block_given_it_cached() -> None:
    cache: RecentCache[str, int] = RecentCache(size=100)
    cache.put("outside", 1)
    shelf = Shelf()
    with apart(shelf):
        cache.put("first block", 2)
    assert (cache.get("outside"), cache.get("first block")) == (1, None)
    with apart():
        assert cache.get("first block") is None
    with apart(shelf):
        assert (cache.get("outside"), cache.get("first block")) == (None, 2)
    assert (cache.get("outside"), cache.get("first block")) == (1, None)
    shelf.clear()
    with apart(shelf):
        assert cache.get("first block") is None


def test_after_an_action_a_cache_holds_only_what_the_action_looked_up_or_added() -> None:
    cache: RecentCache[str, int] = RecentCache(size=100)
    cache.put("asked", 1)
    cache.put("stale", 2)

    def action() -> int | None:
        cache.put("added", 3)
        return cache.get("asked")

    assert keeping_what_it_uses(action) == 1
    assert cache.get("stale") is None
    assert (cache.get("asked"), cache.get("added")) == (1, 3)


def test_an_action_using_more_lines_than_a_generation_holds_keeps_them_all() -> None:
    cache: RecentCache[int, int] = RecentCache(size=4)
    for key in range(3):
        cache.put(key, key)

    def action() -> None:
        for key in range(6):  # three looked up, three added: the young generation turns once
            if cache.get(key) is None:
                cache.put(key, key)

    keeping_what_it_uses(action)
    assert len(cache) == 6
    assert (cache.get(0), cache.get(5)) == (0, 5)


def test_forgetting_lines_apart_empties_the_blocks_caches_and_keeps_what_was_there_before() -> None:
    cache: RecentCache[str, int] = RecentCache(size=100)
    cache.put("before", 1)
    shelf = Shelf()
    with apart(shelf):
        cache.put("shelved", 2)
    with apart():
        cache.put("inside", 3)
        forget_lines()
        assert cache.get("inside") is None
    assert cache.get("before") == 1
    with apart(shelf):
        assert cache.get("shelved") == 2


def test_a_cache_apart_never_turns_over() -> None:
    cache: RecentCache[int, int] = RecentCache(size=4)
    with apart():
        for key in range(10):  # a text longer than a generation: the block prunes its caches itself
            cache.put(key, key)
        assert len(cache) == 10
        assert cache.get(0) == 0
    for key in range(10):
        cache.put(key, key)
    assert len(cache) <= 8


def test_what_is_held_about_a_line_still_parsed_outlives_re_reads_that_did_not_ask() -> None:
    """A migration checks its original, re-reads it after each of four passes, then checks it again:
    the findings of the lines no pass edited are wanted then, though no re-read asked for them."""
    parses: RecentCache[str, object] = RecentCache(size=100, holds_contents=True)
    facts: RecentCache[object, str] = RecentCache(size=100)
    kept, edited = object(), object()  # two lines' parses: the key of what later caches hold about them
    with apart():
        parses.put("a = 1", kept)
        parses.put("b = 2", edited)
        facts.put(kept, "facts of a = 1")
        facts.put(edited, "facts of b = 2")
        keeping_what_it_uses(lambda: parses.get("a = 1"))  # "b = 2" was edited away
        keeping_what_it_uses(lambda: parses.get("a = 1"))
        keeping_what_it_uses(lambda: parses.get("a = 1"))
        assert (facts.get(kept), facts.get(edited)) == ("facts of a = 1", None)
        keeping_what_it_uses(lambda: None)  # "a = 1" edited away too
        assert (facts.get(kept), parses.get("a = 1")) == (None, None)
