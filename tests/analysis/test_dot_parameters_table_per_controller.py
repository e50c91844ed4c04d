"""Each controller's highest axis and channel of the "Dot Parameters" table pass; the number after it is an error.

The table (000:5611-5636) gives, per controller, the axis numbers and the digital input, digital output, ADC,
DAC, auxiliary DAC, encoder and auxiliary encoder channels, and CAN buses 1 to 2 everywhere. A number past them
is the motion library's error: 2 an axis, 4 a channel, 7 an input, 8 an output, 31 a CAN bus (000:18514-18536,
18623). NextMove PCI's inputs and outputs are counted with its two expansion cards, 59 and 35 (footnote 8 at
000:5958-5959, 000:9388-9389), as the checker assumes them fitted. MintDrive's DAC is its drive's speed
demand on axis 0 (000:8764-8765; footnote 7 at 000:5666), and the table prints N/A for ServoNode 51's DAC and
for the auxiliary DACs of the NextMove controllers, whose DAC and AUXDAC entries tick none of them (000:8722,
6665): there the keyword itself is missing, error 17.
"""

from __future__ import annotations

import pytest

import mintlang

# (controller, keyword, program, highest number, error one past it)
_TABLE = [
    # axes: 0-11, 0-7, 0-7, x = 0, x = 0
    ("nextmove-pci", "SPEED", "SPEED.{} = 10\n", 11, "E0002"),
    ("nextmove-pc", "SPEED", "SPEED.{} = 10\n", 7, "E0002"),
    ("nextmove-bx", "STOP", "STOP[{}]\n", 7, "E0002"),
    ("mintdrive", "SPEED", "SPEED.{} = 10\n", 0, "E0002"),
    ("servonode51", "POS", "DIM v\nv = POS.{}\n", 0, "E0002"),
    # digital inputs: 0-19 (59 with two cards), 0-23, 0-15, 0-5, 0-17
    ("nextmove-pc", "IN", "DIM v\nv = IN.{}\n", 23, "E0007"),
    ("mintdrive", "IN", "DIM v\nv = IN{}\n", 17, "E0007"),
    ("servonode51", "INSTATE", "DIM v\nv = INSTATE.{}\n", 5, "E0007"),
    # digital outputs: 0-11 (35 with two cards), 0-11, 0-7, 0-2, 0-8
    ("nextmove-pc", "OUT", "OUT.{} = 1\n", 11, "E0008"),
    ("mintdrive", "OUT", "OUT{} = 1\n", 8, "E0008"),
    # ADC channels: 0-11, 0-7, 0-7, x = 0, 0-3
    ("nextmove-pci", "ADC", "DIM v\nv = ADC.{}\n", 11, "E0004"),
    ("nextmove-pc", "ADCMODE", "ADCMODE.{} = 0\n", 7, "E0004"),
    ("servonode51", "ADC", "DIM v\nv = ADC.{}\n", 0, "E0004"),
    # DAC channels: 0-11, 0-7, 0-3, N/A, N/A (MintDrive's axis 0)
    ("nextmove-pci", "DAC", "DAC.{} = 1\n", 11, "E0004"),
    ("nextmove-pc", "DAC", "DAC.{} = 1\n", 7, "E0004"),
    ("nextmove-bx", "DACLIMITMAX", "DACLIMITMAX.{} = 1\n", 3, "E0004"),
    ("mintdrive", "DAC", "DAC.{} = 1\n", 0, "E0004"),
    # auxiliary DAC channels: N/A, N/A, N/A, 0-1, 0-3
    ("servonode51", "AUXDAC", "AUXDAC.{} = 1\n", 1, "E0004"),
    ("mintdrive", "AUXDAC", "AUXDAC.{} = 1\n", 3, "E0004"),
    # encoder channels: 0-11, 0-7, 0-3, x = 0, x = 0
    ("nextmove-pci", "ENCODER", "DIM v\nv = ENCODER.{}\n", 11, "E0004"),
    ("nextmove-pc", "ENCODERVEL", "DIM v\nv = ENCODERVEL.{}\n", 7, "E0004"),
    ("nextmove-bx", "ENCODERWRAP", "ENCODERWRAP.{} = 100\n", 3, "E0004"),
    ("mintdrive", "FASTENCODER", "DIM v\nv = FASTENCODER.{}\n", 0, "E0004"),
    ("servonode51", "ENCODERSCALE", "ENCODERSCALE.{} = 10\n", 0, "E0004"),
    # auxiliary encoder channels: 0-2, x = 0, x = 0, x = 0, x = 0
    ("nextmove-pci", "AUXENCODER", "DIM v\nv = AUXENCODER.{}\n", 2, "E0004"),
    ("nextmove-pc", "AUXENCODERWRAP", "AUXENCODERWRAP.{} = 100\n", 0, "E0004"),
    ("nextmove-bx", "AUXENCODERVEL", "DIM v\nv = AUXENCODERVEL.{}\n", 0, "E0004"),
    ("mintdrive", "AUXENCODERSCALE", "AUXENCODERSCALE.{} = 10\n", 0, "E0004"),
    ("servonode51", "FASTAUXENCODER", "DIM v\nv = FASTAUXENCODER.{}\n", 0, "E0004"),
    # CAN buses: 1-2 on each controller
    ("nextmove-bx", "REMOTEIN", "DIM v\nv = REMOTEIN.{}.5\n", 2, "E0031"),
    ("servonode51", "REMOTEIN", "DIM v\nv = REMOTEIN.{}.5\n", 2, "E0031"),
]


def _errors(source: str, controller: str) -> list[str]:
    return [d.code for d in mintlang.check(source, controller=controller) if d.code.startswith("E")]


@pytest.mark.parametrize(
    ("controller", "template", "highest"),
    [pytest.param(c, t, h, id=f"{c}-{k}") for c, k, t, h, _ in _TABLE],
)
def test_the_highest_number_of_the_table_passes(controller: str, template: str, highest: int) -> None:
    assert _errors(template.format(highest), controller) == []


@pytest.mark.parametrize(
    ("controller", "template", "highest", "code"),
    [pytest.param(c, t, h, e, id=f"{c}-{k}") for c, k, t, h, e in _TABLE],
)
def test_the_number_after_it_is_the_libraries_error(controller: str, template: str, highest: int, code: str) -> None:
    assert _errors(template.format(highest + 1), controller) == [code]


@pytest.mark.parametrize(
    ("source", "controller"),
    [
        pytest.param("DAC.0 = 1\n", "servonode51", id="servonode51-DAC"),
        pytest.param("AUXDAC.0 = 1\n", "nextmove-pci", id="nextmove-pci-AUXDAC"),
        pytest.param("AUXDAC.0 = 1\n", "nextmove-bx", id="nextmove-bx-AUXDAC"),
    ],
)
def test_a_channel_the_table_prints_na_is_a_missing_keyword(source: str, controller: str) -> None:
    assert _errors(source, controller) == ["E0017"]
