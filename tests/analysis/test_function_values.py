"""A function gets as many values as its format brackets; another count is error 2003.

Counts worked out from the v4 guide's formats: POW(x, y) two (000:15152), SIN(<angle>),
INT(<expression>), ABS (<expression>) one each (000:15944 ...), COMMS( {node, } element) one
or two (braces are optional items, 000:5578-5579), CAMTABLE ( axis, position array, {master
increment array} ) three, NULL written for a master array left out (000:7957-7958).
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.placed import placed_codes


@pytest.mark.parametrize(
    ("source", "column"),
    [
        pytest.param("DIM a\na = POW(2)\nPRINT a\n", 5, id="POW-one-value"),
        pytest.param("DIM a\na = POW(2, 3, 4)\nPRINT a\n", 5, id="POW-three-values"),
        pytest.param("DIM a\na = 1 + SIN(30, 2)\nPRINT a\n", 9, id="SIN-two-values-inside-an-expression"),
        pytest.param("DIM a\na = INT(1.5, 2)\nPRINT a\n", 5, id="INT-two-values"),
        pytest.param("DIM a\nCOMMS(1, 2, 3) = a\n", 1, id="COMMS-three-values"),
        pytest.param("DIM t(3)\nCAMTABLE(0)\nPRINT t(1)\n", 1, id="CAMTABLE-axis-only"),
        pytest.param("DIM t(3)\nCAMTABLE(0, t, NULL, t)\n", 1, id="CAMTABLE-four-values"),
    ],
)
def test_a_wrong_count_is_error_2003_at_the_call(source: str, column: int) -> None:
    assert placed_codes(source) == [("E2003", 2, column)]


def test_the_message_gives_the_count_and_the_format() -> None:
    (diagnostic,) = mintlang.check("PRINT POW(2)\n")
    assert diagnostic.message.endswith("POW takes 2 values (v = POW(x, y)), not 1")


@pytest.mark.parametrize(
    "source",
    [
        pytest.param("PRINT POW(2, 3)\n", id="POW"),
        pytest.param("PRINT ABS (7 * -5)\n", id="ABS-entry-example"),  # 000:6130
        pytest.param("DIM a\na = SIN 90 + a\nPRINT a\n", id="SIN-without-brackets"),  # 000:1395
        pytest.param("DIM a = COMMS(1)\nCOMMS(2, 5) = a\n", id="COMMS-with-and-without-node"),
        pytest.param("DIM p(3)\nCAMTABLE(0, p, NULL)\n", id="CAMTABLE-three"),
        pytest.param("DIM p(3)\nDIM m(2)\nCAMTABLE(1, p, m)\n", id="CAMTABLE-with-master-table"),
        pytest.param("IF POW(2, 2) > 3 THEN PRINT CHR(65)\n", id="inside-IF-THEN"),
    ],
)
def test_the_counts_the_formats_give_are_clean(source: str) -> None:
    assert placed_codes(source) == []
