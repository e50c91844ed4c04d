"""A file's findings kept as found in their lines, each placed when read, read as the placed findings would."""

from __future__ import annotations

from array import array

import mintlang
from mintlang.diagnostics import Diagnostic, Severity, Span
from mintlang.syntax.packed import PlacedDiagnostics
from mintlang.syntax.parser import parse

_PAREN = Diagnostic("E2004", Severity.ERROR, Span(4, 5), "Parentheses error: there is a ')' too many", mint_error=2004)


def test_each_finding_is_read_at_its_lines_offset() -> None:
    placed = PlacedDiagnostics((_PAREN, _PAREN), array("q", [0, 10]))
    assert list(placed) == [_PAREN, _PAREN.shifted(10)]
    assert placed[1].span == Span(14, 15)
    assert placed[-1] == _PAREN.shifted(10)
    assert len(placed) == 2


def test_a_slice_and_a_tuple_of_the_same_findings_are_equal() -> None:
    placed = PlacedDiagnostics((_PAREN, _PAREN, _PAREN), array("q", [0, 10, 20]))
    placed_later = (_PAREN.shifted(10), _PAREN.shifted(20))
    assert placed[1:] == placed_later
    assert placed_later == placed[1:]  # a tuple on the left asks the packed sequence
    assert placed != (_PAREN,) * 3
    assert PlacedDiagnostics((), array("q")) == ()


def test_findings_already_placed_keep_their_spans() -> None:
    assert tuple(PlacedDiagnostics.placed([_PAREN.shifted(7)])) == (_PAREN.shifted(7),)


def test_equal_broken_lines_are_each_reported_at_their_own_place() -> None:
    # "a = 1 )" has one ')' too many at column 7 (E2004, as the manual's bracket example); the
    # same line three times is parsed once, and reported on lines 1, 2 and 3.
    source = "DIM a\n" + "a = 1 )\n" * 3
    document = parse(source)
    lines = [document.line_index.position(d.span.start) for d in document.parse_issues]
    assert [(p.line, p.column) for p in lines] == [(2, 7), (3, 7), (4, 7)]
    found = mintlang.check(source)
    assert [(d.code, d.span) for d in found] == [("E2004", Span(s, s + 1)) for s in (12, 20, 28)]
