"""A v4 keyword MintMT addresses otherwise keeps its v4 abbreviation: the notes write none (MT-1 reads v4 where they
show nothing else), so ``SSD(0)`` is ``SUSPEND(0)`` in MintMT as ``MR(0)`` is ``MOVER(0)``.

The abbreviations are the v4 guide's: SUSPEND SSD (000:17775), MOVEBUFFERFREE MBF (000:14552, 17689),
MOVEBUFFERSIZE MB (000:14568, 17698), MOVEBUFFERID MBI (000:14556), MOVEBUFFERLOW MBW (000:14564),
CONTOURMODE CTM (000:17554), FEEDRATE FR, FEEDRATEMODE FRM and FEEDRATEOVERRIDE FRO (000:10463-10471).
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.migrate.mintmt import to_mintmt
from mintlang.runtime.run import run_source

ABBREVIATED = [
    pytest.param("MB(0) = 4", id="MB"),
    pytest.param("PRINT MBF(0)", id="MBF"),
    pytest.param("MBI(0) = 2", id="MBI"),
    pytest.param("MBW(0) = 1", id="MBW"),
    pytest.param("SSD(0) = 0", id="SSD"),
    pytest.param("CTM(0) = _ctmCONTOUR_ON", id="CTM"),
    pytest.param("FR(0) = 20", id="FR"),
    pytest.param("FRM(0) = _frFEEDRATE", id="FRM"),
    pytest.param("FRO(0) = 50", id="FRO"),
]


@pytest.mark.parametrize("line", ABBREVIATED)
def test_the_v4_abbreviation_reads_as_its_keyword(line: str) -> None:
    found = mintlang.check(line + "\n", dialect="mintmt")
    assert [d.code for d in found if d.code.startswith("E")] == []


def test_the_abbreviations_run_as_the_keywords() -> None:
    source = "MB(0) = 5\nMR(0) = 10\nPRINT MBF(0)\nPRINT SSD(0)\n"
    assert run_source(source, dialect="mintmt", config="RESETALL\n").terminal == "4\n0\n"


def test_a_migrated_abbreviation_checks_as_mintmt() -> None:
    migrated = to_mintmt("MR.0 = 10 : GO.0\nSSD.0 = 1\nPRINT MBF.0\n").text
    assert migrated == "MR(0) = 10 : GO(0)\nSSD(0) = 1\nPRINT MBF(0)\n"
    assert [d.code for d in mintlang.check(migrated, dialect="mintmt") if d.code.startswith("E")] == []
