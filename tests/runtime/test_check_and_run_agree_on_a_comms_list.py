"""mint check and mint-run judge alike each element a ``COMMS(i) = a, b, ...`` list writes.

The program has 99 general elements; 100 onwards are mapped onto the controller's parameters (000:8290-8293),
and a list fills consecutive elements (002:115). So ``COMMS(99) = 1, 2`` writes 2 to element 100, axis 0's
position, which can only be read (000:2586-2590): error 45 (000:18676-18678), which the run raised and the check passed.
"""

from __future__ import annotations

import pytest

from tests.analysis.placed import placed_codes
from tests.runtime.running import simulate

HANDLER = 'END\n#ONERROR\nPRINT "ERR ", ERR, " ERL ", ERL\nRETURN\n'


@pytest.mark.parametrize(
    ("line", "expected", "error"),
    [
        pytest.param("COMMS(99) = 1, 2", [("E0045", 1, 16)], 45, id="second-value-on-axis-0-position"),
        pytest.param("COMMS(98) = 1, , 3", [("E0045", 1, 18)], 45, id="skipped-place-still-counts"),
        pytest.param("COMMS(107) = 1, 2", [("E0045", 1, 7), ("E0046", 1, 17)], 45, id="folerror-then-reserved"),
    ],
)
def test_each_value_is_judged_at_the_element_it_lands_on(
    line: str, expected: list[tuple[str, int, int]], error: int
) -> None:
    assert placed_codes(line + "\n") == expected
    result = simulate(f'{line}\nPRINT "after"\n' + HANDLER)
    assert result.terminal.startswith(f"ERR {error} ERL 1\n")


def test_a_list_within_the_general_elements_passes_both() -> None:
    line = "COMMS(97) = 1, 2, 3"
    assert placed_codes(line + "\n") == []
    assert simulate(f'{line}\nPRINT "after"\n').terminal.endswith("after\n")
