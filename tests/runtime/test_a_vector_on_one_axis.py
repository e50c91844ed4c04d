"""A vector move names two axes or more (000:16958, 17031-17045): on one it is error 2001, as a circle on one
(``mint check`` says the same of ``VECTORR[0]``), and nothing moves; so is a vector with a position left out."""

from __future__ import annotations

import pytest

import mintlang
from tests.runtime.running import simulate


@pytest.mark.parametrize(
    "source",
    [
        "VECTORR[0] = 5 : GO[0]\n",
        "AXES[1]\nVECTORA = 5 : GO\n",
        "VECTORA[0,1] = 5 : GO[0,1]\n",  # the axes past the values are left out (000:578-580): one is left
    ],
)
def test_a_vector_on_one_axis_is_a_missing_parameter(source: str) -> None:
    # a vector move names two axes or more (000:16958, 17031-17045), as a circle two: error 2001
    result = simulate(source)
    assert (result.err, result.erl, result.axes[0].pos, result.axes[1].pos) == (2001, source.count("\n"), 0, 0)


@pytest.mark.parametrize(
    "line",
    [
        pytest.param("VECTORR[0,1] = ,100", id="the first position left out"),
        pytest.param("VECTORA[0,1,2] = 10,20,", id="the last"),
        pytest.param("VECTORA = ,,5", id="on the default axes"),
    ],
)
def test_a_vector_position_left_out_is_a_missing_parameter_in_the_check_too(line: str) -> None:
    # a vector interpolates each axis it moves from one start to one end (000:16958, 17031): a place left
    # empty is 2001 when the line runs, and mint check says so of the whole statement
    source = f"{line}\n"
    assert [(d.code, source[d.span.start : d.span.end]) for d in mintlang.check(source)] == [("E2001", line)]
    result = simulate(f"{line} : GO\n")
    assert (result.err, result.axes[1].pos) == (2001, 0)
