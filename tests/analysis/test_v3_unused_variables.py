"""W103 in Mint v3: only a DIM declares a variable that can go unused.

The v3 guide declares a variable by any assignment to it, and by FOR and INPUT
(001:1348-1360); DIM reserves arrays (001:7299). So the write that declares a v3
variable is also its first use, as the write after a DIM is in v4 (where
``DIM b`` then ``b = 2`` gets no W103). The guide's own subroutine counts ten
moves with a FOR variable it never reads (001:5430-5436): that is no unused variable.
"""

from __future__ import annotations

import pytest

import mintlang


def _findings(source: str) -> list[tuple[str, int]]:
    index = mintlang.LineIndex(source)
    return [(d.code, index.position(d.span.start).line) for d in mintlang.check(source, dialect="v3")]


@pytest.mark.parametrize(
    "source",
    [
        pytest.param(
            "GOSUB move_10\nEND\n#move_10\nFOR i = 0 to 10\n  MOVER = 1 : GO\nNEXT\nRETURN\n",
            id="guide-move_10-counter",
        ),
        pytest.param("INPUT a USING 5,2\n", id="INPUT-declares"),
        pytest.param("b = 2\n", id="assignment-declares"),
        pytest.param("c(3) = 1\n", id="element-write-declares"),
    ],
)
def test_a_variable_declared_by_its_first_write_is_not_unused(source: str) -> None:
    assert [code for code, _ in _findings(source)] == []


def test_an_array_dimmed_and_never_used_is_still_w103() -> None:
    assert _findings("DIM spare(5)\nDIM used(3)\nused(1) = 2\n") == [("W103", 1)]
