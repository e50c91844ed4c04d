"""An axis or channel out of range names what the controller has: one alone where its table gives ``x = 0``.

The Dot Parameters table (000:5612-5621) gives MintDrive and ServoNode 51 the axis ``x = 0`` and ServoNode
51 the ADC channel ``x = 0``; NextMove BX the axes ``0 ≤ x ≤ 7``. "(axes 0)" read as a list cut short.
"""

from __future__ import annotations

import pytest

import mintlang


def _errors(source: str, controller: str) -> list[tuple[str, str]]:
    found = mintlang.check_application(source, dialect="v4", controller=controller).program
    return [(d.code, d.message) for d in found if d.code.startswith("E")]


@pytest.mark.parametrize(
    ("source", "controller", "error"),
    [
        (
            "SPEED.1 = 5\n",
            "mintdrive",
            ("E0002", "Axis specified out of range: axis 1 does not exist on MintDrive (axis 0 only)"),
        ),
        (
            "PRINT ADC.5\n",
            "servonode51",
            ("E0004", "Channel out of range: ADC channel 5 does not exist on ServoNode 51 (channel 0 only)"),
        ),
        (
            "SPEED.8 = 5\n",
            "nextmove-bx",
            ("E0002", "Axis specified out of range: axis 8 does not exist on NextMove BX (axes 0 to 7)"),
        ),
    ],
)
def test_the_message_names_the_axes_or_channels_the_controller_has(source, controller, error) -> None:
    assert _errors(source, controller) == [error]
