"""``OUTX(channel)`` names one output channel (004:148), as v4's dot does (``OUT.channel``, 000:14892): a
channel keyword addresses one channel a call, never several (000:548-549). ``OUTX(0,1) = 1`` is therefore
written as no format shows it, the syntax error 2003 (000:18920-18924) that ``OUT.0.1 = 1`` is in v4, in
``mint check`` and in ``mint-run``; both let it pass, and mint-run set output 0 alone. So is a channel glued
to its keyword (``OUT1``, 000:1114) with brackets after it, as ``OUT1.2`` is in v4."""

from __future__ import annotations

import pytest

import mintlang
from mintlang.runtime.run import run_source
from mintlang.runtime.simulation import Limits
from tests.analysis.checking import covered, only


def _program(line: str) -> str:
    return f'Dim a\nPRINT "before"\n{line}\nPRINT a\n'


def _codes(source: str) -> list[str]:
    return [d.code for d in mintlang.check(source, dialect="mintmt")]


SEVERAL_CHANNELS = [
    pytest.param("OUTX(0,1) = 1", ",1)", "OUTX takes one channel number between its brackets", id="output-written"),
    pytest.param("a = OUTX(2,3)", ",3)", "OUTX takes one channel number between its brackets", id="output-read"),
    pytest.param("a = IN(1,5)", ",5)", "IN takes one channel number between its brackets", id="input-read"),
    pytest.param("OUT1(2) = 1", "(2)", "OUT1 already names channel 1: no brackets after it", id="glued-channel"),
]


@pytest.mark.parametrize(("line", "second", "says"), SEVERAL_CHANNELS)
def test_mint_check_reports_the_second_channel(line: str, second: str, says: str) -> None:
    source = _program(line)
    assert _codes(source) == ["E2003"]
    diagnostic = only(source, "E2003", dialect="mintmt")
    assert (covered(source, diagnostic), diagnostic.message) == (second, f"Syntax error: {says}")


@pytest.mark.parametrize(("line", "second", "says"), SEVERAL_CHANNELS)
def test_mint_run_stops_before_the_program_starts(line: str, second: str, says: str) -> None:
    result = run_source(_program(line), dialect="mintmt", config="RESETALL\n", limits=Limits(until_ms=1000))
    assert result.terminal == "C2003: PROGRAM Syntax error [line 3]\n"
    assert result.stop.message == f"C2003: PROGRAM Syntax error: {says} [line 3]"


@pytest.mark.parametrize("line", ["OUTX(0) = _ON", "a = OUTX(35)", "a = IN(1)", "MOVEOUTX(0,1) = 0", "GO(0,1)"])
def test_one_channel_and_several_axes_pass(line: str) -> None:
    assert _codes(_program(line)) == []
