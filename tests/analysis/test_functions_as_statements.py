"""A function is written where its formats write it.

SIN, POW and the other functions have only formats that read them (``v = SIN(<angle>)``,
000:15944; ``v = POW(x, y)``, 000:15152). Written alone, such a keyword is neither read nor
given a value (#2005, 000:18930-18934); given a value, it is written although it can only be
read (#2000, 000:18905-18908). COMMS has a format that gives it a value and one that reads it
(``COMMS( {node, } element) = <expression>``), so alone it is #2005 too; CAMTABLE's format is
a statement of its own (``CAMTABLE ( axis, position array, {master increment array} )``).
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.placed import placed_codes


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        pytest.param("PRINT 1\nSIN(30)\n", [("E2005", 2, 1)], id="SIN-alone"),
        pytest.param("PRINT 1\n  POW(2, 3)\n", [("E2005", 2, 3)], id="POW-alone"),
        pytest.param("PRINT 1\nCOMMS(1)\n", [("E2005", 2, 1)], id="COMMS-alone"),
        pytest.param("PRINT 1\nABS(1) = 5\n", [("E2000", 2, 1)], id="ABS-given-a-value"),
    ],
)
def test_a_function_out_of_its_formats_is_an_error(source: str, expected: list[tuple[str, int, int]]) -> None:
    assert placed_codes(source) == expected


def test_the_message_shows_how_to_read_it() -> None:
    (diagnostic,) = mintlang.check("SIN(30)\n")
    assert diagnostic.message.endswith("SIN must be read here, as in 'v = SIN(…)'")


@pytest.mark.parametrize(
    "source",
    [
        pytest.param("DIM p(3)\nCAMTABLE(0, p, NULL)\n", id="CAMTABLE-statement"),
        pytest.param("COMMS(1) = 2\nCOMMS(2, 5) = 3\n", id="COMMS-given-a-value"),
        pytest.param("DIM a = COMMS(1)\nPRINT SIN(30) + a\n", id="reads"),
    ],
)
def test_the_formats_own_statements_are_clean(source: str) -> None:
    assert placed_codes(source) == []
