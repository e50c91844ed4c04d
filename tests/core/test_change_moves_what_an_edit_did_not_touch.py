"""What was found outside an edit's window moves with the text; what reaches into it is found again."""

from __future__ import annotations

from mintlang.codes import own
from mintlang.diagnostics import Edit, Fix, Span
from mintlang.syntax.change import Change

# Lines 10 to 20 of the previous text became 10 to 23: everything from 20 on moved 3 characters.
CHANGE = Change(
    start=10, old_end=20, new_end=23, previous_length=50, first_line=1, old_lines=1, new_lines=1, line_shift=0
)


def test_a_span_before_the_window_stays_and_one_after_it_moves() -> None:
    assert CHANGE.span(Span(2, 8)) == Span(2, 8)
    assert CHANGE.span(Span(25, 30)) == Span(28, 33)


def test_a_span_that_ends_where_the_window_starts_stays() -> None:
    assert CHANGE.span(Span(4, 10)) == Span(4, 10)


def test_a_span_that_starts_where_the_window_ends_moves() -> None:
    assert CHANGE.span(Span(20, 22)) == Span(23, 25)


def test_a_span_in_the_window_or_ending_where_it_ends_is_found_again() -> None:
    assert CHANGE.span(Span(12, 14)) is None
    assert CHANGE.span(Span(10, 12)) is None
    assert CHANGE.span(Span(4, 20)) is None  # took in the window's last line break


def test_a_span_over_the_whole_window_and_beyond_moves_its_end() -> None:
    assert CHANGE.span(Span(4, 30)) == Span(4, 33)


def test_a_diagnostic_moves_with_its_fixes_or_is_found_again() -> None:
    fix = Fix("Replace", (Edit(Span(30, 32), "x"),))
    moved = CHANGE.diagnostic(own("W103", Span(25, 27), "unused", fixes=(fix,)))
    assert moved is not None
    assert (moved.span, moved.fixes[0].edits[0].span) == (Span(28, 30), Span(33, 35))
    into_the_window = Fix("Replace", (Edit(Span(12, 13), "x"),))
    assert CHANGE.diagnostic(own("W103", Span(25, 27), "unused", fixes=(into_the_window,))) is None


def test_spliced_keeps_what_was_before_puts_the_window_s_between_and_moves_the_rest() -> None:
    before, inside, after = own("W1", Span(2, 3), "a"), own("W2", Span(12, 13), "b"), own("W3", Span(30, 31), "c")
    found_now = own("W4", Span(15, 16), "d")
    assert CHANGE.spliced((before, inside, after), [found_now]) == (before, found_now, after.shifted(3))
