"""A keyword written with '=' and no value, or PAUSE with no condition, is error 2005, No expression.

Commas skip axes, ``SPEED = ,10`` writing axis 1 only (000:632-641), and a semicolon gives the
last value to the axes left (000:657-663); but when every place after '=' is empty the keyword is
given nothing, which is #2005: a keyword neither read nor assigned a value (000:18930-18934).
``SPEED.0 =`` passed mint check. PAUSE waits for a condition (000:15023); ``PAUSE`` alone passed
too, though mint-run stops it with 2005.
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.placed import placed_codes


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        pytest.param("SPEED.0 =\n", [("E2005", 1, 10)], id="nothing-after-equals"),
        pytest.param("SPEED[0,1] = ,\n", [("E2005", 1, 15)], id="every-axis-skipped"),
        pytest.param("SPEED = ;\n", [("E2005", 1, 10)], id="no-last-value-to-repeat"),
        pytest.param("MOVEA = : GO\n", [("E2005", 1, 8)], id="before-another-statement"),
        pytest.param("COMMS(1) =\n", [("E2005", 1, 11)], id="function-style"),
        pytest.param("OUT1 =\n", [("E2005", 1, 7)], id="channel-suffix"),
        pytest.param("PAUSE\n", [("E2005", 1, 6)], id="pause-without-condition"),
        pytest.param("PAUSE : GO\n", [("E2005", 1, 6)], id="pause-before-another-statement"),
    ],
)
def test_a_keyword_given_no_value_is_error_2005_where_the_value_is_missing(
    source: str, expected: list[tuple[str, int, int]]
) -> None:
    assert placed_codes(source) == expected


@pytest.mark.parametrize("source", ["SPEED = ,10\n", "SPEED[0,1,2] = 10,20;\n", "COMMS(1) = 0\n"])
def test_a_value_for_any_axis_is_enough(source: str) -> None:  # 000:632-641, 657-663, 2449
    assert placed_codes(source) == []


def test_the_message_names_the_keyword_as_written() -> None:
    (diagnostic,) = mintlang.check("OUT1 =\n")
    assert diagnostic.message.endswith("OUT1 is given no value after '='")
