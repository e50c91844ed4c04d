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
