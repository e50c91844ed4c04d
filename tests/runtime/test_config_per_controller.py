"""CONFIG reads each controller's own power-up value, after DEFAULT too (000:8401-8424).

The attributes table gives NextMove "1 and 2" (servo axes 1, the reference profile's four axes are
servo), MintDrive 0 and ServoNode 51 1; DEFAULT puts an axis back as at power-up (000:8981-8983).
"""

from __future__ import annotations

import pytest

from tests.runtime.running import simulate


@pytest.mark.parametrize(
    ("controller", "config"), [("nextmove-pci", "1"), ("nextmove-bx", "1"), ("mintdrive", "0"), ("servonode51", "1")]
)
def test_config_at_power_up_is_the_controllers_default(controller: str, config: str) -> None:
    assert simulate("PRINT CONFIG.0\n", controller=controller).terminal == f"{config}\n"


def test_default_puts_mintdrive_config_back_to_0() -> None:
    source = "CONFIG.0 = _cfSERVO\nPRINT CONFIG.0\nDEFAULT.0\nPRINT CONFIG.0\n"
    assert simulate(source, controller="mintdrive").terminal == "1\n0\n"
