"""mint-run takes a keyword's accepted values from its attributes table, a list of modes included."""

from __future__ import annotations

import pytest

from mintlang.keyworddb.model import Controller
from mintlang.runtime.errors import MintError
from mintlang.runtime.ranges import check_range, table_bounds


def test_a_table_that_lists_modes_takes_those_values_only() -> None:
    """LIMITMODE's table gives 0 <= x <= 3, 5 on every controller (000:13469): 4 is no mode."""
    bounds = table_bounds("LIMITMODE", Controller.NEXTMOVE_PCI)
    assert bounds.allowed == frozenset({0.0, 1.0, 2.0, 3.0, 5.0})
    assert check_range("LIMITMODE", 5.0, bounds) == 5.0
    with pytest.raises(MintError) as raised:
        check_range("LIMITMODE", 4.0, bounds)
    assert raised.value.code == 3
    assert "it takes 0, 1, 2, 3 or 5" in str(raised.value)


@pytest.mark.parametrize(
    ("value", "written"),
    [
        pytest.param(8388607.5, "8388607.5", id="half-past-the-end"),
        pytest.param(-8388607.5, "-8388607.5", id="half-before-the-start"),
        pytest.param(16777216.0, "16777216", id="whole-number-every-digit"),
    ],
)
def test_the_error_shows_the_value_as_written(value: float, written: str) -> None:
    """POS's range is -8388607.0 to 8388607.0 at SCALE 1 (000:15110-15111, 15133): 8388607.5 is outside by a half,
    which the message keeps, rather than rounding it to the 8388608 of seven digits."""
    with pytest.raises(MintError) as raised:
        check_range("POS", value, table_bounds("POS", Controller.NEXTMOVE_PCI))
    assert f"(POS = {written}; it takes -8388607 to 8388607)" in str(raised.value)
