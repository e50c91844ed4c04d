"""A write whose axis or channel and value are both wrong stops on the axis or channel, as ``mint check`` says.

The axis after the dot is error 2 when the controller lacks it, an I/O channel error 4, and a value
outside the keyword's range error 3 (000:18514-18525); the dot parameters table gives the numbers each
controller has: axis 0 alone on MintDrive, 0 to 11 on a NextMove PCI, whose ADC channels are 0 to 11
too (000:5614, 5620). The guide gives no order when both are wrong: ``mint check`` reports the number after
the dot first, and the run stops on it (``ranges.ranged``'s channel resolver), with ``ERRAXIS`` the number
written (000:9942-9943, 9952-9954). A value alone out of range is still error 3, on the axis or channel written.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.runtime.run import run_source

HANDLER = 'END\n#ONERROR\nPRINT ERR, " ", ERRAXIS\nRETURN\n'


def _checked(line: str, controller: str, dialect: str) -> list[str]:
    found = mintlang.check(line + "\n", controller=controller, dialect=dialect)
    return [finding.code for finding in found if finding.code.startswith("E")]


@pytest.mark.parametrize(
    ("controller", "dialect", "line", "checked", "printed"),
    [
        pytest.param("mintdrive", "v4", "ACCELTIME.1 = -1", ["E0002", "E0003"], "2 1", id="ACCELTIME axis 1"),
        pytest.param("mintdrive", "v4", "DECELTIME.1 = -1", ["E0002", "E0003"], "2 1", id="DECELTIME axis 1"),
        pytest.param("mintdrive", "v4", "DRIVEENABLE.1 = 5", ["E0002", "E0003"], "2 1", id="DRIVEENABLE axis 1"),
        pytest.param("nextmove-pci", "v4", "ADCMODE.12 = 77", ["E0004", "E0003"], "4 12", id="ADCMODE channel 12"),
        pytest.param(
            "nextmove-pci", "mintmt", "FEEDRATEOVERRIDE(12) = -1", ["E0002", "E0003"], "2 12", id="MintMT feedrate"
        ),
        pytest.param(
            "nextmove-pci", "mintmt", "MOVEBUFFERLOW(12) = -1", ["E0002", "E0003"], "2 12", id="MintMT buffer low"
        ),
        pytest.param("mintdrive", "v4", "ACCELTIME.0 = -1", ["E0003"], "3 0", id="value alone on axis 0"),
        pytest.param("nextmove-pci", "v4", "ADCMODE.11 = 77", ["E0003"], "3 11", id="value alone on channel 11"),
    ],
)
def test_the_run_stops_on_the_error_the_check_reports_first(
    controller: str, dialect: str, line: str, checked: list[str], printed: str
) -> None:
    assert _checked(line, controller, dialect) == checked
    result = run_source(f"{line}\n{HANDLER}", controller=controller, dialect=dialect)
    assert result.terminal == f"{printed}\n"
