"""CAMTABLE names its axis first, and an axis the controller lacks is error 2.

The guide writes ``CAMTABLE ( axis, position array, {master increment array} )`` and lists
the axis number among its dot parameters (000:7907-7910); the axis numbers each controller
has are 0 to 11 on NextMove PCI and 0 alone on MintDrive (000:5611-5613), and an axis number
the controller does not support is error 2, "Axis specified out of range" (000:18514-18517).
"""

from __future__ import annotations

import pytest

import mintlang

TABLE = "DIM p(3) = 2, 10, 20\n"


@pytest.mark.parametrize(
    ("statement", "controller", "axis"),
    [
        pytest.param("CAMTABLE(12, p, NULL)\n", "nextmove-pci", "12", id="past-the-twelve-axes"),
        pytest.param("CAMTABLE ( 1, p, NULL )\n", "mintdrive", "1", id="second-axis-of-a-one-axis-drive"),
        pytest.param("IF IN1 THEN CAMTABLE(8, p, NULL)\n", "nextmove-bx", "8", id="after-then"),
    ],
)
def test_an_axis_past_the_controllers_is_error_2(statement: str, controller: str, axis: str) -> None:
    source = TABLE + statement
    [finding] = mintlang.check(source, controller=controller)
    assert (finding.code, source[finding.span.start : finding.span.end]) == ("E0002", axis)


@pytest.mark.parametrize(
    ("statement", "controller"),
    [
        pytest.param("CAMTABLE(11, p, NULL)\n", "nextmove-pci", id="last-axis"),
        pytest.param("CAMTABLE(0, p, p)\n", "mintdrive", id="the-one-axis"),
    ],
)
def test_an_axis_the_controller_has_is_clean(statement: str, controller: str) -> None:
    assert mintlang.check(TABLE + statement, controller=controller) == []
