"""A name close to a keyword and given a list of values is that keyword misspelt: error 3007 at the name.

A variable holds one value, so ``name = 1, 2`` can only be a keyword written for several axes
(v4 000:632-641). Before, the line only said "unexpected ','". The v3 guide's own listing writes
``MFOLEERR = 10,10`` (001:4773) for the keyword it names MFOLERR elsewhere (001:634, 843).
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.placed import placed_codes


@pytest.mark.parametrize(
    ("source", "dialect", "meant"),
    [
        pytest.param("VECTRR = 100,200,300\n", "v4", "VECTORR", id="v4-three-axes"),
        pytest.param("SPED = 1, 2\n", "v4", "SPEED", id="v4-two-axes"),
        pytest.param("SPED.0 = 1, 2\n", "v4", "SPEED", id="v4-with-an-axis"),
        pytest.param("MFOLEERR = 10,10 : REM Max following error\n", "v3", "MFOLERR", id="v3-guide-listing"),
    ],
)
def test_the_error_names_the_keyword_it_resembles(source: str, dialect: str, meant: str) -> None:
    (diagnostic,) = mintlang.check(source, dialect=dialect)
    assert (diagnostic.code, diagnostic.span.start) == ("E3007", 0)
    assert f"did you mean '{meant}'" in diagnostic.message
    assert [edit.text for fix in diagnostic.fixes for edit in fix.edits] == [meant]


@pytest.mark.parametrize(
    "source",
    [
        pytest.param("DIM a\na = 1, 2\n", id="a-name-like-no-keyword"),
        pytest.param("DIM a(2)\na(1, 2) = 1\n", id="a-comma-inside-brackets"),
    ],
)
def test_other_lists_are_still_a_syntax_error_2003(source: str) -> None:
    assert [code for code, _, _ in placed_codes(source)] == ["E2003"]
