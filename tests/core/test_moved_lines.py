"""Lines moved by edits are read as if each had been made again at its new place."""

from __future__ import annotations

import bisect
from array import array

from hypothesis import given
from hypothesis import strategies as st

from mintlang.syntax.moved import LINE_NUMBER, MovedLines, MovedOffsets, bisect_left, bisect_right

OFFSETS = (0, 10, 25, 31, 40, 52)


def test_the_items_after_the_replaced_ones_move_and_those_before_stay() -> None:
    moved = MovedOffsets.spliced(OFFSETS, (2, 3), (25, 29), 4, 0)
    assert list(moved) == [0, 10, 25, 29, 35, 44, 56]
    assert len(moved) == 7


def test_an_item_is_moved_when_read_without_moving_the_others() -> None:
    moved = MovedOffsets.spliced(OFFSETS, (2, 3), (25, 29), 4, 0)
    assert (moved[1], moved[4], moved[-1]) == (10, 35, 56)
    assert tuple(moved[3:5]) == (29, 35)
    assert repr(moved) == "MovedOffsets(7 in 3 pieces)"  # nothing made yet


def test_typing_in_one_place_keeps_three_pieces() -> None:
    moved = OFFSETS
    for _ in range(50):
        moved = MovedOffsets.spliced(moved, (2, 3), (25,), 1, 0)
    assert list(moved) == [0, 10, 25, *(offset + 50 for offset in OFFSETS[3:])]
    assert "in 3 pieces" in repr(MovedOffsets.spliced(moved, (2, 3), (25,), 1, 0))


def test_edits_in_many_places_are_made_into_one_sequence_again() -> None:
    moved = tuple(range(0, 400, 10))
    made_again = 0
    for line in range(1, 39, 2):
        moved = MovedOffsets.spliced(moved, (line, line + 1), (moved[line],), 1, 0)
        made_again += not isinstance(moved, MovedOffsets)  # past the most pieces kept
        assert isinstance(moved, array) or int(repr(moved).split(" in ")[1].split()[0]) <= 16
    assert made_again == 2  # each edit elsewhere adds two pieces: 17 at the 8th and at the 16th
    assert list(moved)[-1] == 390 + 19


def test_moved_lines_keep_their_syntax_and_move_their_origin_and_number() -> None:
    import mintlang  # noqa: PLC0415 - the parser, for real lines

    lines = mintlang.parse("a = 1\nb = 2\nc = 3\n").placed
    moved = MovedLines.spliced(lines, (0, 1), lines[:1], 3, 1)
    assert moved[2].syntax is lines[2].syntax
    assert (moved[2].origin, moved[2].number) == (lines[2].origin + 3, lines[2].number + 1)
    assert moved == tuple(moved)


@given(
    st.lists(st.integers(0, 1000), min_size=1, max_size=30).map(sorted),
    st.lists(st.tuples(st.integers(0, 30), st.integers(0, 3), st.integers(-5, 5)), max_size=30),
)
def test_any_run_of_splices_reads_as_the_same_splices_of_a_list(
    start: list[int], splices: list[tuple[int, int, int]]
) -> None:
    expected = list(start)
    moved: object = tuple(start)
    for at, count, shift in splices:
        first = min(at, len(expected))
        end = min(first + count, len(expected))
        replacement = expected[first:end]
        expected = expected[:first] + replacement + [value + shift for value in expected[end:]]
        moved = MovedOffsets.spliced(moved, (first, end), tuple(replacement), shift, 0)  # type: ignore[arg-type]
        assert [moved[index] for index in range(len(expected))] == expected  # type: ignore[index]
    assert list(moved) == expected  # type: ignore[call-overload]


@given(
    st.lists(st.integers(0, 1000), min_size=1, max_size=30).map(sorted),
    st.lists(st.tuples(st.integers(0, 30), st.integers(0, 3), st.integers(0, 5)), max_size=30),
    st.integers(-5, 1200),
)
def test_searching_moved_items_finds_what_searching_them_made_again_finds(
    start: list[int], splices: list[tuple[int, int, int]], value: int
) -> None:
    expected = list(start)
    moved: object = tuple(start)
    for at, count, shift in splices:  # moving the items after the replaced ones further on keeps them sorted
        first = min(at, len(expected))
        end = min(first + count, len(expected))
        expected = expected[:first] + expected[first:end] + [item + shift for item in expected[end:]]
        moved = MovedOffsets.spliced(moved, (first, end), tuple(expected[first:end]), shift, 0)  # type: ignore[arg-type]
        assert bisect_left(moved, value) == bisect.bisect_left(expected, value)  # type: ignore[arg-type]
        assert bisect_right(moved, value) == bisect.bisect_right(expected, value)  # type: ignore[arg-type]


def test_moved_lines_are_searched_by_their_moved_numbers() -> None:
    import mintlang  # noqa: PLC0415 - the parser, for real lines

    lines = mintlang.parse("a = 1\nb = 2\nc = 3\n").placed  # lines 1, 2, 3
    moved = MovedLines.spliced(lines, (0, 1), lines[:1], 3, 2)  # lines 1, 4, 5
    assert [bisect_left(moved, number, key=LINE_NUMBER) for number in range(1, 7)] == [0, 1, 1, 1, 2, 3]
    assert [bisect_right(moved, number, key=LINE_NUMBER) for number in range(1, 7)] == [1, 1, 1, 2, 3, 3]
