"""A semicolon after the last value applies it to every axis left (000:654-659, 1098): ``VECTORA[0,1] = 5;``
gives both axes a position, so it is a vector through two axes (000:16958, 17031), not the one position that
``VECTORA[0,1] = 5`` gives (000:578-580), and it runs to (5, 5)."""

from __future__ import annotations

import pytest

from tests.analysis.placed import placed
from tests.runtime.running import simulate


@pytest.mark.parametrize(
    ("source", "dialect"),
    [
        ("VECTORA[0,1] = 5;\n", "v4"),
        ("VECTORR[0,1,2] = 5;\n", "v4"),
        ("AXES[0,1]\nVECTORR = 7;\n", "v4"),
        ("VECTORA(0,1) = 5;\n", "mintmt"),
        ("VECTORA([0,1]) = 5;\n", "mintmt"),
    ],
)
def test_mint_check_finds_a_position_for_every_axis(source: str, dialect: str) -> None:
    assert placed(source, "code", "text", codes="E", dialect=dialect) == []


def test_the_run_moves_both_axes_there() -> None:
    result = simulate("VECTORA[0,1] = 5; : GO[0,1]\nPAUSE IDLE[0,1]\n")
    assert (result.err, result.axes[0].pos, result.axes[1].pos) == (-1, 5, 5)
