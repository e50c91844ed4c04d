"""What a check keeps per line is shared where it can be, and reads as it did.

Issue 17, item 10: memory within 50 times the input. Equal spans, equal token
shapes, equal line keys and equal numbers at the same place are one object each; the physical lines are kept as
an array of offsets beside the lexed lines, and still read as ``(offset, line)``.
"""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

import mintlang
from mintlang.diagnostics import Span
from mintlang.syntax.lexer import lex
from mintlang.syntax.spans import SHARED_BELOW, span


def test_equal_small_spans_are_one_object() -> None:
    assert span(3, 8) is span(3, 8)
    assert span(3, 8) == Span(3, 8)


def test_a_span_reaching_past_a_line_of_the_controller_is_made_afresh_and_still_equal() -> None:
    far = span(10, SHARED_BELOW + 5)
    assert far == Span(10, SHARED_BELOW + 5)
    assert far is not span(10, SHARED_BELOW + 5)


@given(st.integers(0, 600), st.integers(0, 600))
def test_a_span_is_the_span_of_its_start_and_end(start: int, end: int) -> None:
    start, end = min(start, end), max(start, end)
    assert span(start, end) == Span(start, end)


def test_two_lines_of_the_same_shape_share_their_token_kinds_and_offsets() -> None:
    first, second = (line for _, line in lex("a = 1\nb = 2\n").lines)
    assert first.kinds is second.kinds
    assert first.starts is second.starts and first.ends is second.ends
    assert first.texts == ("a", "=", "1") and second.texts == ("b", "=", "2")


def test_the_nodes_of_two_different_lines_share_their_spans() -> None:
    first, second = mintlang.parse("a = 1\nb = 2\n").placed
    assert first.syntax is not second.syntax
    assert first.syntax.statements[0].span is second.syntax.statements[0].span


def test_repeated_lines_share_one_key_for_what_they_were_parsed_from() -> None:
    lines = mintlang.parse("GO\nPAUSE IDLE.0\nGO\n").placed
    assert lines[0].content is lines[2].content
    assert lines[0].number != lines[2].number


def test_a_line_read_in_another_dialect_or_for_another_controller_has_a_key_of_its_own() -> None:
    keys = [
        mintlang.parse("GO\n", dialect, controller=controller).placed[0].content
        for dialect in ("v4", "mintmt")
        for controller in ("nextmove-pci", "mintdrive")
    ]
    assert len({id(key) for key in keys}) == 4


def test_a_line_that_names_no_macro_shares_its_key_with_the_same_line_where_none_is_defined() -> None:
    with_macros = mintlang.parse("DEFINE fast = 100\nDIM a\nPRINT a\n").placed
    without = mintlang.parse("DIM a\nPRINT a\n").placed
    assert with_macros[1].content is without[0].content
    assert with_macros[2].content is without[1].content


def test_equal_numbers_at_the_same_place_of_two_lines_are_one_node() -> None:
    first, second, third = mintlang.parse("a = 10\nb = 10\nc = 12\n").placed
    ten = first.syntax.statements[0].value
    assert ten is second.syntax.statements[0].value
    assert (ten.text, ten.value) == ("10", 10.0)
    assert third.syntax.statements[0].value.value == 12.0


def test_physical_lines_read_as_offset_and_line_pairs() -> None:
    source = "DIM a\r\n\na = 1 : REM set\nPRINT a"
    physical = mintlang.parse(source).physical
    pairs = list(physical)
    assert [offset for offset, _ in pairs] == [0, 7, 8, 24]
    assert [line.text for _, line in pairs] == ["DIM a\r\n", "\n", "a = 1 : REM set\n", "PRINT a"]
    assert len(physical) == 4
    assert physical[2] == pairs[2] and physical[-1] == pairs[-1]
    assert list(physical[1:3]) == pairs[1:3]
    assert "".join(line.text for _, line in physical) == source


def test_the_physical_lines_between_two_offsets_are_found_by_their_offsets() -> None:
    document = mintlang.parse("DIM a\r\n\na = 1 : REM set\nPRINT a")
    assert list(document.physical_between(0, 0)) == [0]
    assert list(document.physical_between(8, 30)) == [2, 3]
    assert [token.text for token in document.tokens_in(24, 24)] == ["PRINT", " ", "a"]


def test_checking_on_several_controllers_one_after_another_gives_each_its_own_findings() -> None:
    # Line findings are kept per file and controller; the cache of one never answers for another.
    # A MintDrive and a ServoNode 51 drive one axis, 0: HOME.3 names an axis they do not have (error 2).
    source = "HOME.3 = 1\n"
    one_axis = {mintlang.Controller.MINTDRIVE, mintlang.Controller.SERVONODE51}
    for controller in [*mintlang.Controller, *reversed(mintlang.Controller)]:
        codes = [d.code for d in mintlang.check(source, controller=controller)]
        assert codes == (["E0002"] if controller in one_axis else [])


def test_an_occurrence_is_where_its_name_is_written_in_the_file() -> None:
    source = "DIM total\nREM add\ntotal = total + 1\n"
    model = mintlang.build_model(mintlang.parse(source))
    symbol = model.symbols.variables["TOTAL"]
    spans = [occurrence.span for occurrence in symbol.occurrences()]
    assert sorted(spans) == [Span(4, 9), Span(18, 23), Span(26, 31)]  # a write is recorded after its value
    assert {source[span.start : span.end] for span in spans} == {"total"}
