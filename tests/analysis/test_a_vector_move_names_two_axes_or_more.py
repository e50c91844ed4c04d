"""VECTORA and VECTORR interpolate a straight line through two axes or more: their formats list
``axis0,axis1 {,axis2}`` and the guide says at least two must be given (000:16958, 17031-17045).
One axis is a parameter missing, 2001, as for a circle; four are valid (000:3221, VECTORR on four axes).
One position leaves one axis too, since the axes past the values are left out (000:578-580).
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.placed import placed


@pytest.mark.parametrize(
    ("source", "dialect", "written"),
    [
        ("VECTORR[0] = 5\n", "v4", "[0]"),
        ("VECTORA.1 = 5\n", "v4", ".1"),
        ("VECTORA(0) = 5\n", "mintmt", "(0)"),
    ],
)
def test_one_axis_is_a_missing_parameter(source: str, dialect: str, written: str) -> None:
    assert placed(source, "code", "text", codes="E", dialect=dialect) == [("E2001", written)]


@pytest.mark.parametrize(
    "source", ["VECTORR[1,2] = 100,200\n", "VECTORA[0,1,2] = 1,2,3\n", "VECTORR[0,1,2,3] = 10,20,30,40\n"]
)
def test_two_axes_or_more_are_valid(source: str) -> None:
    assert placed(source, "code", "text", codes="E") == []


def test_the_message_says_what_is_missing() -> None:
    (error,) = mintlang.check_application("VECTORR[0] = 5\n").program
    assert error.message == "Missing parameter: VECTORR interpolates two axes or more, 1 listed"


@pytest.mark.parametrize(
    ("source", "written"),
    [("VECTORA[0,1] = 5\n", "5"), ("AXES[0,1]\nVECTORR = 7\n", "7")],
)
def test_one_position_is_a_missing_parameter(source: str, written: str) -> None:
    assert placed(source, "code", "text", codes="E") == [("E2001", written)]


def test_fewer_positions_than_axes_but_two_are_valid() -> None:
    assert placed("VECTORA[0,1,2] = 1, 2\n", "code", "text", codes="E") == []
