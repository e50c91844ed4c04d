"""Writing a COMMS element the controller maps onto a parameter it only reads is error 45.

COMMS elements 100 to 219 hold 15 parameters of each of the eight axes, 220 to 255 the I/O and
other data (000:2566-2584). Of each axis, offsets 0 to 7 are read only (POS, VEL, AXISMODE,
AXISERROR, DAC, ENCODER, IDLE, FOLERROR); of the I/O block, the inputs (offset 0), the analog
channels, the error data and the status words (4 to 17) and the build number (19) are read only,
and only the digital outputs (offset 2) may be written (000:2586-2650). A write to a read-only
element is run-time error 45, "COMMS element is read only" (000:18676-18678); mint check passed it.
"""

from __future__ import annotations

import pytest

from tests.analysis.placed import placed_codes


@pytest.mark.parametrize(
    "source",
    [
        pytest.param("COMMS(99) = 1\n", id="general-element"),
        pytest.param("COMMS(222) = 1\n", id="digital-outputs-read-write"),
        pytest.param("DIM a\na = COMMS(100)\n", id="read-axis-0-position"),
        pytest.param("DIM a\na = COMMS(5,239)\n", id="read-remote-build-number"),
    ],
)
def test_general_and_writable_elements_and_reads_are_accepted(source: str) -> None:
    assert placed_codes(source) == []


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        pytest.param("COMMS(100) = 5\n", [("E0045", 1, 7)], id="axis-0-position"),
        pytest.param("COMMS(107) = 5\n", [("E0045", 1, 7)], id="axis-0-following-error"),
        pytest.param("COMMS(205) = 5\n", [("E0045", 1, 7)], id="axis-7-position"),
        pytest.param("COMMS(220) = 5\n", [("E0045", 1, 7)], id="digital-inputs"),
        pytest.param("COMMS(224) = 5\n", [("E0045", 1, 7)], id="analog-channel-0"),
        pytest.param("COMMS(239) = 5\n", [("E0045", 1, 7)], id="build-number"),
        pytest.param("COMMS(5,130) = 5\n", [("E0045", 1, 9)], id="remote-axis-2-position"),
    ],
)
def test_writing_a_read_only_element_is_error_45_at_the_element(
    source: str, expected: list[tuple[str, int, int]]
) -> None:
    assert placed_codes(source) == expected
