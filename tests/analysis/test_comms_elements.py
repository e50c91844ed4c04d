"""COMMS, the array Mint defines, has elements 1 to 255: another one is error 2016, Invalid index.

Its 99 general elements and the locations 100 to 255 mapped onto the controller's parameters
(000:8287-8293, 2566-2584) are all there is, on this node or on another one written
``COMMS(node, element)`` (000:2556-2559). Like an index outside a DIMmed array's 1 .. size (#2016,
000:19038-19046), COMMS(0) or COMMS(256) names no element. Both passed mint check.
"""

from __future__ import annotations

import pytest

from tests.analysis.placed import placed_codes


@pytest.mark.parametrize(
    "source",
    ["COMMS(1) = 0\n", "COMMS(99) = 1\n", "COMMS(5,10) = 100\n", "DIM a\na = COMMS(255)\n"],
)
def test_elements_1_to_255_are_accepted(source: str) -> None:  # 000:2449, 2559
    assert placed_codes(source) == []


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        pytest.param("COMMS(0) = 1\n", [("E2016", 1, 7)], id="element-0"),
        pytest.param("COMMS(256) = 1\n", [("E2016", 1, 7)], id="element-256"),
        pytest.param("COMMS(5,300) = 1\n", [("E2016", 1, 9)], id="remote-element"),
        pytest.param("DIM a\na = COMMS(0) + 1\n", [("E2016", 2, 11)], id="read"),
    ],
)
def test_an_element_outside_1_to_255_is_error_2016_at_the_element(
    source: str, expected: list[tuple[str, int, int]]
) -> None:
    assert placed_codes(source) == expected


def test_an_element_too_large_for_a_mint_number_is_error_3_alone() -> None:
    """The literal is beyond binary32 (000:714-716), error 3 where it is written; no element is named, for
    the number the checker would name is its double-precision rounding, which the user never wrote."""
    element = "1" + "0" * 39
    assert placed_codes(f"DIM a\na = COMMS({element})\n") == [("E0003", 2, 11)]
