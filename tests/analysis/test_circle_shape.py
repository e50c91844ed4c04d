"""A circle names two axes in its brackets and writes three values.

CIRCLEA and CIRCLER print one format each, ``[axis0,axis1] = <centre0>,<centre1>,<angle>``
(000:8152, 000:8215). A third axis is more than the keyword supports (#2017), an axis
left out is a missing parameter in the brackets (#2001), and a fourth value has nothing
to take it (#2017, as for values past the listed axes of any other keyword). A value left out
is a missing parameter too: the format has no optional part, every example of the guide writes all
three, and ``mint-run`` refuses a circle without its centre and angle.
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.placed import placed_codes


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        pytest.param("CIRCLEA[0,1] = 10, 20, 90, 5\n", [("E2017", 1, 28)], id="fourth-value"),
        pytest.param("CIRCLER[0,1,2] = 1, 2, 3\n", [("E2017", 1, 8)], id="third-axis"),
        pytest.param("CIRCLEA[0] = 1, 2, 3\n", [("E2001", 1, 8)], id="one-axis"),
        pytest.param("CIRCLEA[0,1] = 5, 6\n", [("E2001", 1, 1)], id="no-angle"),
        pytest.param("CIRCLER[0,1] = 1,,90\n", [("E2001", 1, 1)], id="a-centre-left-out"),
        pytest.param("AXES[0,1]\nCIRCLEA = 1, 2\n", [("E2001", 2, 1)], id="default-axes-no-angle"),
        pytest.param("AXES[0,1]\nCIRCLEA = 1, 2, 3, 4\n", [("E2017", 2, 20)], id="default-axes-fourth-value"),
    ],
)
def test_a_circle_of_another_shape_is_an_error(source: str, expected: list[tuple[str, int, int]]) -> None:
    assert placed_codes(source) == expected


def test_the_message_shows_the_format() -> None:
    (diagnostic,) = mintlang.check("CIRCLER[0,1,2] = 1, 2, 3\n")
    assert "CIRCLER[axis0,axis1] = <centre0>,<centre1>,<angle> moves two axes, 3 listed" in diagnostic.message


@pytest.mark.parametrize(
    "source",
    [
        pytest.param("CIRCLEA[0,1] = 20, 20, 180 : GO[0,1]\n", id="three-values-on-two-axes"),
        pytest.param("CIRCLER[2,3] = -10, -10, 180\n", id="any-two-axes"),
        pytest.param("AXES[0,1]\nCIRCLEA = 20,20,180 : GO\n", id="default-axes-as-the-guide-writes-it"),  # 000:3260
        pytest.param("SPEED[0,1] = 10, 20\n", id="other-keywords-unchanged"),
    ],
)
def test_the_format_s_shape_is_clean(source: str) -> None:
    assert placed_codes(source) == []
