"""A write without axes goes to the AXES list set before it, one value an axis (000:590-606, 627-639).

``AXES[0,1]`` then ``SPEED = 10,20,30`` is ``SPEED[0,1] = 10,20,30``, which has a value more than its
axes (000:572-576): error 2017, "Too many parameters" (000:19047). Fewer values than axes are valid
(``MOVEA[0,1,2] = 10,20``, 000:578-580), and a skipped place skips an axis (``SPEED = ,,20`` with
AXES[0,1,2] sets axis 2, 000:638-639).

AXES is set as the program runs, so the list is only known where the AXES statement is surely the last
one to have run: not past a label a jump may land on, a GOSUB whose subroutine may set another, or a
conditional statement.
"""

from __future__ import annotations

import pytest

from tests.analysis.placed import placed_codes


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        pytest.param("AXES[0,1]\nSPEED = 10, 20, 30\n", ("E2017", 2, 17), id="a-value-more"),
        pytest.param("AXES[0,1]\nSPEED = ,,,20\n", ("E2017", 2, 12), id="past-the-list-after-empty-places"),
        pytest.param("AXES[0]\nMOVER = 5, 5\n", ("E2017", 2, 12), id="one-axis-listed"),
        pytest.param("AXES[0,1] : MOVEA = 1, 2, 3\n", ("E2017", 1, 27), id="on-the-same-line"),
        pytest.param("AXES[0,1]\nDIM a\na = 1\nPRINT a\nSPEED = 1, 2, 3\n", ("E2017", 5, 15), id="past-plain-lines"),
        pytest.param(
            "AXES[0,1,2]\nGOSUB s\nAXES[0]\nMOVER = 5, 5\nEND\n#s\nRETURN\n", ("E2017", 4, 12), id="a-list-set-anew"
        ),
    ],
)
def test_more_values_than_the_axes_listed_is_an_error(source: str, expected: tuple[str, int, int]) -> None:
    assert placed_codes(source) == [expected]


@pytest.mark.parametrize(
    "source",
    [
        pytest.param("AXES[0,1,2]\nMOVEA = 10, 20\n", id="fewer-values-than-axes"),
        pytest.param("AXES[0,1,2]\nSPEED = ,,20\n", id="a-skipped-place-for-each-axis"),
        pytest.param("AXES[0,1]\nKVEL = 10;\n", id="fill-is-one-value"),
        pytest.param("AXES[0,1]\nSPEED[0,1,2] = 1, 2, 3\n", id="axes-written-with-the-keyword"),
        pytest.param("AXES[0,1]\nAXES[0,1,2]\nSPEED = 1, 2, 3\n", id="a-later-list-is-in-force"),
        pytest.param(
            "AXES[0,1]\nGOSUB wide\nSPEED = 1, 2, 3\nEND\n#wide\nAXES[0,1,2]\nRETURN\n", id="a-subroutine-sets-it"
        ),
        pytest.param("DIM a\nAXES[0,1]\nIF a THEN AXES[0,1,2]\nSPEED = 1, 2, 3\n", id="set-on-a-condition"),
        pytest.param(  # the jump arrives with the controller's twelve axes
            "DIM a\nIF a THEN GOTO go\nAXES[0,1]\n#go\nSPEED = 1, 2, 3\n", id="after-a-label-a-jump-lands-on"
        ),
    ],
)
def test_values_the_axes_in_force_may_take_are_clean(source: str) -> None:
    assert [code for code, _, _ in placed_codes(source) if code == "E2017"] == []
