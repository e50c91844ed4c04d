"""Lines and columns of offsets, and the text of a line, at every line end Mint and editors know."""

from __future__ import annotations

import pytest

from mintlang.diagnostics import LineIndex, Position


@pytest.mark.parametrize("text", ["DIM a\nb = 1\n", "DIM a\r\nb = 1\r\n", "DIM a\rb = 1\r"])
def test_each_line_text_leaves_out_its_line_break(text: str) -> None:
    index = LineIndex(text)
    assert [index.line_text(line) for line in (1, 2, 3)] == ["DIM a", "b = 1", ""]


def test_a_line_past_the_text_is_empty() -> None:
    index = LineIndex("PRINT 1")
    assert (index.line_text(0), index.line_text(1), index.line_text(2)) == ("", "PRINT 1", "")


def test_an_offset_after_a_crlf_starts_the_next_line() -> None:
    index = LineIndex("DIM a\r\nb = 1")
    assert index.position(7) == Position(2, 1)
