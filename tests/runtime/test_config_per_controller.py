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
    assert simulate(source, controller="mintdrive", enable=False).terminal == "1\n0\n"


def test_config_refuses_an_enabled_drive_with_error_90() -> None:
    """The drive must be disabled to change the configuration (000:8481): error #90, "Action not possible when
    axis is enabled", names the axis (000:18821-18823)."""
    result = simulate('PRINT "set-up"\nCONFIG.1 = _cfOFF\n')
    assert (result.err, result.erl) == (90, 2)
    message = "R0090: PROGRAM Action not possible when axis is enabled [axis/channel 1] [line 2]\n"
    assert result.terminal.endswith(message)


def test_config_after_the_drive_is_disabled() -> None:
    source = "DRIVEENABLE.1 = 0\nCONFIG.1 = _cfOFF\nPRINT CONFIG.1\n"
    assert simulate(source).terminal == "0\n"
