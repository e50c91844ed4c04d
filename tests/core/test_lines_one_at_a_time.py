"""A file's lines read one at a time are the lines split_lines lists, line ends included."""

from __future__ import annotations

import pytest

from mintlang.diagnostics import lines_of, split_lines


@pytest.mark.parametrize(
    ("text", "lines"),
    [
        ("a\nb\n", ["a\n", "b\n"]),
        ("a\r\nb", ["a\r\n", "b"]),
        ("a\rb\r\r", ["a\r", "b\r", "\r"]),
        ("a\fb\x85c\n", ["a\fb\x85c\n"]),  # a form feed or NEL ends no Mint line
        ("", []),
    ],
)
def test_lines_one_at_a_time_are_the_listed_lines(text: str, lines: list[str]) -> None:
    assert list(lines_of(text)) == lines
    assert list(lines_of(text)) == split_lines(text, keepends=True)
