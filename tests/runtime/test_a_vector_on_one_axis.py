"""A vector move names two axes or more (000:16958, 17031-17045): on one it is error 2001, as a circle on one
(``mint check`` says the same of ``VECTORR[0]``), and nothing moves."""

from __future__ import annotations

import pytest

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
