"""The simulated terminal: PRINT separators and tab stops, INKEY and INPUT (spec PR-4, PR-5), bounded memory."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from mintlang.runtime import terminal as terminal_module
from mintlang.runtime.run import run_source
from mintlang.runtime.terminal import NumberEntry, Terminal

# PR-4: separators


def test_print_with_no_arguments_prints_an_empty_line() -> None:
    terminal = Terminal()
    terminal.print_items([], newline=True)
    assert terminal.text == "\n"


def test_comma_puts_the_next_argument_directly_after() -> None:
    terminal = Terminal()
    terminal.print_items([("a = ", ","), ("5", ","), (" POS = ", ","), ("0", None)], newline=True)
    assert terminal.text == "a = 5 POS = 0\n"


def test_semicolon_moves_to_the_next_tab_stop_every_eight_characters() -> None:
    terminal = Terminal()
    terminal.print_items([("1", ";"), ("22", ";"), ("333", None)], newline=True)
    assert terminal.text == "1       22      333\n"


def test_semicolon_at_a_tab_stop_moves_to_the_following_one() -> None:
    terminal = Terminal()
    terminal.print_items([("12345678", ";"), ("x", None)], newline=True)
    assert terminal.text == "12345678        x\n"


def test_trailing_semicolon_suppresses_the_line_feed_and_pads_to_the_tab_stop() -> None:
    terminal = Terminal()
    terminal.print_items([("10", ";"), ("20", ";")], newline=True)
    assert terminal.text == "10      20      "
    assert terminal.column == 16


def test_trailing_comma_suppresses_the_line_feed() -> None:
    terminal = Terminal()
    terminal.print_items([("Enter ", ",")], newline=True)
    terminal.print_items([("done", None)], newline=True)
    assert terminal.text == "Enter done\n"


def test_carriage_return_rewrites_the_same_line_and_resets_tab_stops() -> None:
    terminal = Terminal()
    terminal.print_items([("100", ";"), ("\r", ",")], newline=True)
    terminal.print_items([("1", ";"), ("2", None)], newline=True)
    assert terminal.text == "100     \r1       2\n"


def test_a_prompt_never_ends_the_line() -> None:
    terminal = Terminal()
    terminal.print_items([("A = ", None)], newline=False)
    assert terminal.text == "A = "


def test_every_write_is_echoed_as_it_happens() -> None:
    pieces: list[str] = []
    terminal = Terminal(echo=pieces.append)
    terminal.print_items([("a", ";"), ("b", None)], newline=True)
    assert "".join(pieces) == terminal.text == "a       b\n"


def test_a_print_statement_reaches_the_live_terminal_in_one_write() -> None:
    pieces: list[str] = []
    run_source('DIM a = 5\nPRINT "a = ", a; "b";\nPRINT "x", 2\n', controller="nextmove-bx", echo=pieces.append)
    assert pieces == ["a = 5   b       ", "x2\n"]


@given(st.lists(st.tuples(st.text(alphabet="abc\r xyz0123", max_size=12), st.sampled_from([",", ";", None]))))
def test_one_write_per_print_leaves_what_a_write_per_item_leaves(items: list[tuple[str, str | None]]) -> None:
    at_once, by_item = Terminal(), Terminal()
    at_once.print_items(items, newline=True)
    for text, separator in items:
        by_item.write(text)
        if separator == ";":
            by_item.write(" " * (8 - by_item.column % 8))
    if not items or items[-1][1] is None:
        by_item.newline()
    assert (at_once.text, at_once.column) == (by_item.text, by_item.column)


@given(st.lists(st.tuples(st.text(alphabet="abc xyz0123", max_size=12), st.sampled_from([",", ";"]))))
def test_semicolons_always_land_on_a_tab_stop(items: list[tuple[str, str]]) -> None:
    terminal = Terminal()
    terminal.print_items(items, newline=True)
    if items and items[-1][1] == ";":
        assert terminal.column % 8 == 0
        assert len(terminal.text) % 8 == 0


# Screen commands in a plain-text log


def test_control_characters_take_no_column() -> None:
    terminal = Terminal()
    terminal.write("ab\a")
    assert terminal.column == 2


def test_beep_writes_the_bell_character() -> None:
    terminal = Terminal()
    terminal.beep()
    assert terminal.text == "\a"


def test_cls_ends_the_current_line_only_when_needed() -> None:
    terminal = Terminal()
    terminal.cls()
    terminal.write("menu")
    terminal.cls()
    assert (terminal.text, terminal.column) == ("menu\n", 0)


def test_locate_pads_to_the_column() -> None:
    terminal = Terminal()
    terminal.locate(10, 10)
    terminal.write("Column 10")
    assert terminal.text == " " * 9 + "Column 10"


def test_locate_left_of_the_cursor_starts_a_new_line() -> None:
    terminal = Terminal()
    terminal.write("abcdef")
    terminal.locate(3, 1)
    assert terminal.text == "abcdef\n  "


def test_locate_out_of_bounds_leaves_the_cursor_where_it_is() -> None:
    terminal = Terminal()
    terminal.write("ab")
    terminal.locate(0, 5)
    assert (terminal.text, terminal.column) == ("ab", 2)


# PR-5: INKEY and INPUT


def test_inkey_is_zero_when_nothing_is_waiting() -> None:
    assert Terminal().inkey() == 0


def test_inkey_returns_keys_in_order_with_letters_upper_cased() -> None:
    terminal = Terminal()
    terminal.type_keys("a1A;")
    assert [terminal.inkey() for _ in range(5)] == [65, ord("1"), 65, ord(";"), 0]


def test_read_line_waits_for_a_line_end() -> None:
    terminal = Terminal()
    terminal.type_keys("12")
    assert terminal.read_line() is None
    terminal.type_keys("3\r")
    assert terminal.read_line() == "123"


def test_crlf_is_one_line_end() -> None:
    terminal = Terminal()
    terminal.type_keys("1\r\n2\n")
    assert [terminal.read_line(), terminal.read_line(), terminal.read_line()] == ["1", "2", None]


def test_a_typed_line_is_echoed_to_the_output() -> None:
    terminal = Terminal()
    terminal.print_items([("A = ", ",")], newline=True)
    terminal.type_keys("42\r")
    terminal.read_line()
    assert (terminal.text, terminal.column) == ("A = 42\n", 0)


def test_input_reads_a_number_as_binary32() -> None:
    terminal = Terminal()
    terminal.type_keys(" -1.5\r0.1\r")
    assert terminal.read_number() == NumberEntry(-1.5, typed="-1.5")
    assert terminal.read_number() == NumberEntry(0.10000000149011612, typed="0.1")


def test_input_of_an_empty_line_keeps_the_variable() -> None:
    terminal = Terminal()
    terminal.type_keys("\r")
    assert terminal.read_number() == NumberEntry(None)


def test_input_of_something_other_than_a_number_asks_again() -> None:
    terminal = Terminal()
    terminal.type_keys("abc\r1e99\r")
    assert terminal.read_number() == NumberEntry(None, retry=True)
    assert terminal.read_number() == NumberEntry(None, retry=True)


def test_input_of_a_number_too_large_for_binary32_asks_again() -> None:
    terminal = Terminal()
    terminal.type_keys("9" * 40 + "\r")
    assert terminal.read_number() == NumberEntry(None, retry=True)


def test_input_before_a_line_is_complete_is_none() -> None:
    terminal = Terminal()
    terminal.type_keys("7")
    assert terminal.read_number() is None


def test_only_the_latest_output_is_kept_and_the_rest_is_counted(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(terminal_module, "TRANSCRIPT_LIMIT", 10)
    terminal = Terminal()
    for line in range(100):
        terminal.write(f"line {line:02}\n")
    assert terminal.text == "8\nline 99\n"
    assert terminal.printed == 800
    assert terminal.dropped == 790


def test_watched_text_is_found_across_writes_however_much_is_dropped(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(terminal_module, "TRANSCRIPT_LIMIT", 10)
    terminal = Terminal()
    terminal.watch("Homed")
    terminal.watch("never")
    for piece in ("Ho", "m", "ed\n", *["x" * 9 + "\n"] * 50):
        terminal.write(piece)
    assert terminal.has_printed("Homed")
    assert not terminal.has_printed("never")
    assert not terminal.has_printed("Homed\n") and terminal.has_printed("xx\n")  # unwatched: what is kept


def test_a_terminal_expectation_sees_output_printed_before_the_kept_part(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(terminal_module, "TRANSCRIPT_LIMIT", 100)
    source = 'REM @expect terminal contains "ready"\nDIM i\nPRINT "ready"\nFOR i = 1 TO 50\n  PRINT "filler"\nNEXT\n'
    result = run_source(source, controller="nextmove-bx")
    (outcome,) = result.outcomes
    assert outcome.held
    assert len(result.terminal) == 100 and result.terminal_dropped == len("ready\n") + 50 * len("filler\n") - 100


@given(st.lists(st.text("ab\n", max_size=4), max_size=12), st.text("ab\n", min_size=1, max_size=4))
def test_watched_text_is_found_exactly_when_the_whole_output_contains_it(pieces: list[str], wanted: str) -> None:
    terminal = Terminal()
    terminal.watch(wanted)
    for piece in pieces:
        terminal.write(piece)
    assert terminal.has_printed(wanted) == (wanted in "".join(pieces))


def test_dec_prints_a_number_as_it_prints_anyway() -> None:
    # PRINT modifiers (v4 guide 15352-15359): DEC is decimal, the default, between HEX and BIN items
    assert run_source("DIM a = 26\nPRINT HEX a; DEC a; BIN a\n").terminal == "1A      26      11010\n"
