"""Where an edit changed a text: what the version before and the one after share at each end."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from mintlang.syntax.common import edited, shared_ends

TEXTS = st.text(alphabet="ab\r\né", max_size=40)


def _shared_by_characters(old: str, new: str) -> tuple[int, int]:
    """Counted one character at a time: the definition."""
    start = 0
    while start < min(len(old), len(new)) and old[start] == new[start]:
        start += 1
    end = 0
    while end < min(len(old), len(new)) - start and old[-1 - end] == new[-1 - end]:
        end += 1
    return start, end


def test_a_character_typed_in_the_middle_leaves_both_sides_shared() -> None:
    assert shared_ends("PRINT 1\nGO\n", "PRINT 12\nGO\n") == (7, 4)


def test_the_end_shared_never_overlaps_the_start_shared() -> None:
    assert shared_ends("aaa", "aaaa") == (3, 0)
    assert shared_ends("abab", "ab") == (2, 0)


@given(TEXTS, TEXTS, TEXTS, TEXTS)
def test_any_two_versions_share_what_comparing_characters_finds(before: str, old: str, new: str, after: str) -> None:
    first, second = before + old + after, before + new + after
    assert shared_ends(first, second) == _shared_by_characters(first, second)
    assert shared_ends(first, second) == _shared_by_characters(first, second)  # asked again: remembered
    assert shared_ends(second, first) == _shared_by_characters(second, first)


EDITS = st.tuples(st.integers(0, 100), st.integers(0, 100), TEXTS)


def _apply(text: str, change: tuple[int, int, str]) -> tuple[str, int, int]:
    """``text`` with a range replaced, as an editor's change makes it, and the range."""
    start, length, typed = change
    start = min(start, len(text))
    end = min(start + length, len(text))
    return text[:start] + typed + text[end:], start, end


@given(TEXTS, EDITS)
def test_what_an_edit_is_said_to_have_changed_gives_what_comparing_characters_finds(
    old: str, change: tuple[int, int, str]
) -> None:
    new, start, end = _apply(old, change)
    edited(old, new, start, end)
    assert shared_ends(old, new) == _shared_by_characters(old, new)


@given(TEXTS, EDITS, EDITS)
def test_two_edits_before_anyone_asks_give_what_comparing_the_first_and_last_finds(
    first: str, change: tuple[int, int, str], next_change: tuple[int, int, str]
) -> None:
    second, start, end = _apply(first, change)
    edited(first, second, start, end)
    third, start, end = _apply(second, next_change)
    edited(second, third, start, end)
    assert shared_ends(first, third) == _shared_by_characters(first, third)


@given(TEXTS, st.lists(st.tuples(EDITS, st.booleans()), max_size=8))
def test_edits_asked_about_or_not_give_what_comparing_any_two_versions_finds(
    first: str, changes: list[tuple[tuple[int, int, str], bool]]
) -> None:
    versions = [first]
    for change, asked in changes:
        new, start, end = _apply(versions[-1], change)
        edited(versions[-1], new, start, end)
        if asked:  # as the language server's analysis asks after a keystroke
            assert shared_ends(versions[-1], new) == _shared_by_characters(versions[-1], new)
        versions.append(new)
    for old in versions:
        assert shared_ends(old, versions[-1]) == _shared_by_characters(old, versions[-1])
