"""A DIM the grammar rejects gives one syntax error, at the DIM, and no error 3001 at each later use.

Every variable is declared with DIM before use (000:897-898), one name per DIM
(000:911-913), and holds a floating point number (000:705-706): a typed
declaration as in other BASICs (``Dim x As Integer``, often MintMT read as v4)
is a syntax error. The name it meant to declare is not reported again at every
later line: the error at the DIM is the one to fix. A use before the broken
DIM is still error 3001, as it would be before a good one.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.dialect import Dialect


def _found(source: str, dialect: Dialect = Dialect.V4) -> list[tuple[str, int]]:
    return [(d.code, d.span.start) for d in mintlang.check(source, dialect=dialect)]


@pytest.mark.parametrize("dialect", [Dialect.V4, Dialect.MINTMT])
def test_a_typed_dim_is_one_syntax_error_at_its_type(dialect: Dialect) -> None:
    source = "Dim x As Integer\nx = 5\nPRINT x\nx = x + 1\nPRINT x * 2\n"
    assert _found(source, dialect) == [("E2003", 6)]  # at "As"


def test_the_syntax_error_says_dim_takes_no_type() -> None:
    (error,) = mintlang.check("DIM rate AS FLOAT\nrate = 2.5\n")
    assert "DIM takes no type" in error.message


def test_a_dim_of_two_names_does_not_cascade_either() -> None:
    # "DIM aVar, thisIsAVariable" is a syntax error (000:911-913); aVar is not reported again
    source = "DIM aVar, thisIsAVariable\naVar = 1\n"
    assert [code for code, _ in _found(source)] == ["E2003"]


def test_a_use_before_the_broken_dim_is_still_undeclared() -> None:
    assert [code for code, _ in _found("x = 1\nDIM x AS INTEGER\nPRINT x\n")] == ["E3001", "E2003"]


def test_another_undeclared_name_is_still_reported() -> None:
    assert [code for code, _ in _found("DIM x AS INTEGER\ny = x\n")] == ["E2003", "E3001"]


def test_an_array_sized_in_square_brackets_is_told_the_round_ones_and_fixed() -> None:
    # DIM array_name(<no_of_elements>) (000:9167); square brackets address axes
    source = "DIM table[10]\ntable(1) = 5\n"
    (error,) = mintlang.check(source)
    assert (error.code, error.span.start) == ("E2003", len("DIM table"))
    assert "round brackets: DIM table(...)" in error.message
    (fix,) = error.fixes
    assert fix.safe and mintlang.diagnostics.with_edits(source, fix.edits) == "DIM table(10)\ntable(1) = 5\n"


def test_no_name_of_a_dim_list_cascades() -> None:
    # each of the names a list meant to declare is the one syntax error's, not an error 3001 at each use
    source = "DIM layer, row, col\nrow = 1\ncol = row\n"
    assert [code for code, _ in _found(source)] == ["E2003"]


def test_a_dim_list_is_told_one_name_per_dim_and_fixed() -> None:
    # one name per DIM (000:911-913); ':' separates statements on a line (000:1560), so the lines stay as they are
    source = "DIM layer, row,col\nlayer = row + col\n"
    (error,) = mintlang.check(source)
    assert (error.code, error.span.start) == ("E2003", len("DIM layer"))
    assert "one variable per DIM: DIM layer : DIM row : DIM col" in error.message
    (fix,) = error.fixes
    assert fix.safe
    assert mintlang.diagnostics.with_edits(source, fix.edits) == "DIM layer : DIM row : DIM col\nlayer = row + col\n"


def test_a_list_of_values_after_an_equals_is_no_list_of_names() -> None:
    (error,) = mintlang.check("DIM a = 1, 2\n")
    assert "one variable per DIM" not in error.message
