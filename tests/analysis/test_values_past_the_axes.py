"""A write gives at most one value for each axis it addresses.

The guide: the values after the ``=`` cannot outnumber the axes given, except for a
circle (000:572-576, ``MOVEA[0,1] = 100,150,500`` is invalid), and error 2017 is
"Too many parameters" (000:19047). A dot names exactly one axis (000:677-681), so a
second value after ``MOVEA.0`` has no axis to take it; a circle needs two axes, so one
named with the dot misses its second (2001, as ``CIRCLEA[0]`` does). Without a selector
the values go to the default axes, which never outnumber the controller's axes
(000:605-606): a thirteenth value on the twelve-axis NextMove PCI is 2017 whatever
AXES says, and a fourth on a one-axis MintDrive. The finding points at the first value
written past the axes: in ``SPEED[0,1] = ,,,20`` the third and fourth places hold
nothing, so it is the 20 (000:636-639: an empty place skips an axis).

What the AXES list is (000:590-606) is checked in ``test_values_past_the_axes_list``.
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.placed import placed_codes


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        pytest.param("MOVEA.0 = 10, 20\n", [("E2017", 1, 15)], id="move-on-one-axis"),
        pytest.param("SPEED.1 = 10, 20, 30\n", [("E2017", 1, 15)], id="parameter-on-one-axis"),
        pytest.param("JOG.(1) = 3, 4\n", [("E2017", 1, 14)], id="axis-as-an-expression"),
        pytest.param("CIRCLEA.0 = 1, 2, 90\n", [("E2001", 1, 8)], id="circle-on-one-axis"),
        pytest.param("SCALE = " + ", ".join(["1"] * 13) + "\n", [("E2017", 1, 45)], id="more-than-any-axes"),
        pytest.param("SPEED[0,1] = ,,,20\n", [("E2017", 1, 17)], id="past-the-list-after-empty-places"),
    ],
)
def test_values_past_the_addressed_axes_are_an_error(source: str, expected: list[tuple[str, int, int]]) -> None:
    assert placed_codes(source) == expected


@pytest.mark.parametrize(
    "source",
    [
        pytest.param("MOVEA.0 = 10\n", id="one-value-for-the-dot"),
        pytest.param("SPEED.0 = 10;\n", id="fill-is-one-value"),
        pytest.param("SCALE = " + ", ".join(["1"] * 12) + "\n", id="one-value-for-each-axis"),
        pytest.param("AXES[0,1,2]\nSPEED = ,,20\n", id="skipped-places"),  # 000:630-640
    ],
)
def test_as_many_values_as_axes_is_clean(source: str) -> None:
    assert placed_codes(source) == []


def test_a_fourth_value_on_a_one_axis_controller_is_an_error() -> None:
    source = "SPEED = ,,,20\n"  # the 20 goes to axis 3; a MintDrive has axis 0 alone
    [finding] = mintlang.check(source, controller="mintdrive")
    assert (finding.code, source[finding.span.start : finding.span.end]) == ("E2017", "20")


def test_a_fourth_value_on_a_four_axis_controller_is_clean() -> None:
    assert mintlang.check("SPEED = ,,,20\n", controller="nextmove-bx") == []  # 000:606-608, AXES[0,1,2,3]
