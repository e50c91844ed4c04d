"""AUXDAC: the auxiliary analog outputs of MintDrive and ServoNode 51, held per channel and read back.

The entry (000:6658-6691) reads or sets an output channel in percent of +10 V ("100 is equivalent to
+10v", 000:6686), default 0 and range -100 ≤ x ≤ 100 (000:6680); fractions give finer control
(000:4198-4209). ServoNode 51 has channels 0 and 1, MintDrive 0 to 3 (000:5623, 6685); the NextMoves have
none (N/A at 000:5623, no tick in the quick reference, 000:18148), so AUXDAC is error 17 there
(000:18570-18575). A value outside the range is #3, a channel the controller lacks #4 (000:18518-18525).
``mint check`` and ``mint-run`` give a line the same verdict.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate

HANDLER = 'END\n#ONERROR\nPRINT "ERR ", ERR, " ERL ", ERL\nRETURN\n'


def _checked(line: str, controller: str) -> list[str]:
    return [d.code for d in mintlang.check(line + "\n", controller=controller) if d.code.startswith("E")]


@pytest.mark.parametrize(
    ("controller", "source", "printed"),
    [
        pytest.param("mintdrive", "PRINT AUXDAC.3\n", "0\n", id="power-up 0"),
        pytest.param("mintdrive", "AUXDAC.1 = 50\nPRINT AUXDAC.1\nPRINT AUXDAC.2\n", "50\n0\n", id="per channel"),
        pytest.param("mintdrive", "AUXDAC.3 = -25\nPRINT AUXDAC.3\n", "-25\n", id="-2.5 V"),
        pytest.param("servonode51", "AUXDAC.1 = 12.5\nPRINT AUXDAC.1\n", "12.5\n", id="a fraction"),
        pytest.param("servonode51", "AUXDAC.0 = 100\nPRINT AUXDAC.0\n", "100\n", id="+10 V, the top"),
        # the guide's own AUXDAC = 25 (000:4200) names no channel: it is channel 0, as ADC's is
        pytest.param("mintdrive", "AUXDAC = 25\nPRINT AUXDAC.0\nPRINT AUXDAC\n", "25\n25\n", id="no channel"),
    ],
)
def test_a_channel_reads_back_what_was_written(controller: str, source: str, printed: str) -> None:
    assert _checked(source, controller) == []
    result = simulate(source, controller=controller)
    assert (result.stop.reason, result.terminal) == (StopReason.END, printed)


@pytest.mark.parametrize(
    ("controller", "line", "checked", "code"),
    [
        pytest.param("mintdrive", "AUXDAC.1 = 150", ["E0003"], 3, id="MintDrive 150"),
        pytest.param("mintdrive", "AUXDAC.0 = -100.5", ["E0003"], 3, id="MintDrive -100.5"),
        pytest.param("servonode51", "AUXDAC.1 = 101", ["E0003"], 3, id="ServoNode 101"),
        pytest.param("servonode51", "AUXDAC.2 = 5", ["E0004"], 4, id="ServoNode channel 2"),
        pytest.param("servonode51", "PRINT AUXDAC.2", ["E0004"], 4, id="ServoNode read channel 2"),
        pytest.param("mintdrive", "AUXDAC.4 = 1", ["E0004"], 4, id="MintDrive channel 4"),
        # both wrong: the check reports the channel first, and the run stops on it
        pytest.param("mintdrive", "AUXDAC.4 = 150", ["E0004", "E0003"], 4, id="channel before value"),
        pytest.param("nextmove-pci", "AUXDAC.0 = 5", ["E0017"], 17, id="PCI write"),
        pytest.param("nextmove-bx", "PRINT AUXDAC.0", ["E0017"], 17, id="BX read"),
    ],
)
def test_check_and_run_give_the_same_error(controller: str, line: str, checked: list[str], code: int) -> None:
    assert _checked(line, controller) == checked
    result = simulate(f'{line}\nPRINT "after"\n' + HANDLER, controller=controller)
    assert result.terminal.startswith(f"ERR {code} ERL 1\n")


def test_a_refused_value_leaves_the_channel_as_it_was() -> None:
    source = "AUXDAC.2 = 40\nAUXDAC.2 = 100.5\nEND\n#ONERROR\nPRINT AUXDAC.2\nRETURN\n"
    assert simulate(source, controller="mintdrive").terminal == "40\n"
