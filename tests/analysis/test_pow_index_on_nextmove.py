"""On NextMove, POW's index must be below 0 or above 1 (000:15163): W121 for a constant index from 0 to 1.

POW(x, y) returns x to the power y (000:15151-15155), and the entry restricts the index y on
NextMove (PCI, PC and BX) alone. The guide names no error for an index from 0 to 1, so the
controller's answer is not known: ``mint check`` warns, and ``mint-run`` computes the power as on
the other controllers (runtime/BEHAVIOUR.md, NM-5).
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.placed import placed

NEXTMOVES = ("nextmove-pci", "nextmove-pc", "nextmove-bx")


def _warned(source: str, controller: str) -> list[tuple[object, ...]]:
    return placed(source, "code", "text", controller=controller, codes="W121")


@pytest.mark.parametrize("controller", NEXTMOVES)
@pytest.mark.parametrize(
    ("source", "index"),
    [
        pytest.param("PRINT POW(4, 0.5)\n", "0.5", id="a-square-root"),
        pytest.param("PRINT POW(4, 0)\n", "0", id="zero"),
        pytest.param("PRINT POW(4, 1)\n", "1", id="one"),
        pytest.param("PRINT POW(8, 1 / 3)\n", "1 / 3", id="a-constant-expression"),
        pytest.param("DEFINE half = 0.5\nPRINT POW(4, half)\n", "half", id="a-macro"),
    ],
)
def test_an_index_from_0_to_1_is_w121_on_nextmove(source: str, index: str, controller: str) -> None:
    assert _warned(source, controller) == [("W121", index)]


@pytest.mark.parametrize("controller", NEXTMOVES)
@pytest.mark.parametrize(
    "source",
    [
        pytest.param("PRINT POW(2, 3)\n", id="the-entry-example"),  # 000:15157-15159
        pytest.param("PRINT POW(2, -1)\n", id="below-0"),
        pytest.param("PRINT POW(4, -0.5)\n", id="a-fraction-below-0"),
        pytest.param("PRINT POW(4, 1.5)\n", id="a-fraction-above-1"),
        pytest.param("DIM y = 0.5\nPRINT POW(4, y)\n", id="a-variable-known-only-when-it-runs"),
    ],
)
def test_an_index_below_0_or_above_1_is_clean(source: str, controller: str) -> None:
    assert _warned(source, controller) == []


@pytest.mark.parametrize("controller", ["mintdrive", "servonode51"])
def test_other_controllers_take_any_index(controller: str) -> None:
    assert _warned("PRINT POW(4, 0.5)\n", controller) == []


def test_the_message_gives_the_index_and_the_controller() -> None:
    (warning,) = [d for d in mintlang.check("PRINT POW(4, 0.5)\n", controller="nextmove-bx") if d.code == "W121"]
    assert warning.message == "POW's index is 0.5: on NextMove BX it must be below 0 or above 1"
