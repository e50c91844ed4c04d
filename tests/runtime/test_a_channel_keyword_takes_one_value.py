"""A channel keyword's write gives one value: a second is error 2017 in ``mint check`` and in the run.

Channel keywords cannot address several channels in one call (000:547-548) and their formats write one
expression (``OUT.x = <expression>``, ``OUTx = <expression>``, 000:14887-14895; MintMT's
``OUTX(channel)``, 004:148), while the values after the ``=`` may not outnumber what they go to
(000:572-576), "Too many parameters" being error 2017 (000:19047). The guide names that error for axes
only, so 2017 rather than a syntax error (2003) is a reading of it. A skipped place counts as a value
(``SPEED = ,10``, 000:634-636), so ``OUT.1 = ,1`` is reported at the 1. Nothing is written: the output
stays off. DAC is left alone: its format shows more values (000:8727).
"""

from __future__ import annotations

import pytest

from mintlang.runtime.run import run_source
from tests.analysis.placed import placed

HANDLER = 'END\n#ONERROR\nPRINT ERR, " ", OUT.1\nRETURN\n'


@pytest.mark.parametrize(
    ("dialect", "line", "second"),
    [
        pytest.param("v4", "OUT.1 = 1, 0", "0", id="OUT.x"),
        pytest.param("v4", "OUT1 = 1, 0", "0", id="OUTx"),
        pytest.param("v4", "OUT = 2, 0", "0", id="the whole word"),
        pytest.param("v4", "OUT.1 = , 1", "1", id="a skipped place"),
        pytest.param("v4", "RELAY = 1, 0", "0", id="RELAY"),
        pytest.param("v4", "ADCMODE.1 = 1, 2", "2", id="ADCMODE"),
        pytest.param("mintmt", "OUTX(1) = 1, 0", "0", id="MintMT OUTX"),
    ],
)
def test_a_second_value_is_too_many_parameters(dialect: str, line: str, second: str) -> None:
    assert placed(line + "\n", "code", "text", dialect=dialect) == [("E2017", second)]
    result = run_source(f"{line}\n{HANDLER}", controller="nextmove-pci", dialect=dialect)
    assert result.terminal.startswith("2017 0\n")


@pytest.mark.parametrize(
    "line",
    [
        pytest.param("OUT.1 = 1", id="one value"),
        pytest.param("OUT.1 = 1;", id="a fill is one value"),
        pytest.param("DAC.0 = 10, 20", id="DAC's format shows more"),
    ],
)
def test_what_the_formats_show_is_no_error(line: str) -> None:
    assert placed(line + "\n", "code", "text", codes="E2017") == []
