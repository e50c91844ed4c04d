"""A parameter whose attributes table has no row for the controller, named alone, is error 2005 in both tools.

#2005 is a keyword "not being read or assigned a value" (000:18930-18933). Without a row for the controller,
the formats say how a keyword is used, and these only read or assign it: ``v = ERR`` (000:9901), ``v = ERL``
(000:9881), ``v = ERRAXIS`` (000:9943), ``v = INKEY.channel`` (000:12145); HOMEINPUT on NextMove PCI, which
its entry supports (000:11534-11535) and whose table prints no NextMove PCI row (000:11552-11555), is written
and read (000:11540-11541); DAC on MintDrive likewise (000:8725-8726, a table of NextMove alone: 000:8737).
mint-run stopped these with 2005 where mint check said nothing; given an operand without '=' they are a
syntax error (2003), as ``SPEED 5`` is.
"""

from __future__ import annotations

import pytest

import mintlang
from tests.runtime.running import simulate


def _checked(line: str, controller: str) -> list[str]:
    return [d.code for d in mintlang.check(line + "\n", controller=controller) if d.code.startswith("E")]


@pytest.mark.parametrize(
    ("line", "controller", "code"),
    [
        pytest.param("ERR", "nextmove-pci", 2005, id="ERR"),
        pytest.param("ERL", "mintdrive", 2005, id="ERL"),
        pytest.param("ERRAXIS", "nextmove-bx", 2005, id="ERRAXIS"),
        pytest.param("INKEY.1", "servonode51", 2005, id="INKEY"),
        pytest.param("HOMEINPUT.0", "nextmove-pci", 2005, id="HOMEINPUT-on-NextMove-PCI"),
        pytest.param("DAC.0", "mintdrive", 2005, id="DAC-on-MintDrive"),
        pytest.param("ERR 5", "nextmove-pci", 2003, id="ERR-given-an-operand"),
        pytest.param("HOMEINPUT 5", "nextmove-pci", 2003, id="HOMEINPUT-given-an-operand"),
    ],
)
def test_both_tools_give_the_same_error(line: str, controller: str, code: int) -> None:
    assert _checked(line, controller) == [f"E{code:04d}"]
    assert simulate(f"{line}\n", controller=controller).err == code
