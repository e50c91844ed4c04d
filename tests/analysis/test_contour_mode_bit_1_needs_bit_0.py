"""CONTOURMODE takes 0, 1 or 3, in ``mint check`` as in ``mint-run``.

Its table prints 0 ≤ x ≤ 3, and its text narrows that: bit 1 (inter-vector angle control) cannot be set
without bit 0 (contouring on) (000:8653-8654). ``mint-run`` refused 2 with error 3 while ``mint check``
passed it; both now read the narrowed range from one place (``keyworddb.supplements.NARROWED``).
"""

from __future__ import annotations

import pytest

from tests.analysis.checking import ERROR, found
from tests.runtime.running import simulate


@pytest.mark.parametrize("mode", ["0", "1", "3", "_ctmCONTOUR_ON + _ctmVECTOR_ANGLE_ON"])
def test_a_mode_with_bit_1_only_beside_bit_0_is_taken(mode: str) -> None:
    program = f"CONTOURMODE.0 = {mode}\nPRINT CONTOURMODE.0\n"
    assert found(program) == []
    assert simulate(program).stop.reason.value == "end"


def test_bit_1_without_bit_0_is_error_3_in_both_tools() -> None:
    program = "CONTOURMODE.0 = 2\n"
    assert found(program) == [("E0003", ERROR, 1)]
    result = simulate(program)
    assert (result.stop.reason.value, result.err) == ("error", 3.0)
