"""A fraction written to a keyword whose values are modes is error 3 in mint check and mint-run alike.

A keyword "will accept fractional values" when its range "specifies a decimal part (.0)"
(000:5647-5650); the ranges of CONFIG (0 - 5), FOLLOWMODE (0 ≤ x ≤ 3), CAM, BANK (0 ≤ x ≤ 2),
STOPINPUTMODE and ADCMODE print none, and their entries list the values as modes, motor types,
cards or bits (000:7345, 000:7595, 000:8431, 000:10846). A value "outside of the accepted range of
values" is #3, "Data specified out of range" (000:18518-18521). A gain is no mode: KDERIV's range
prints no decimal part either, yet its entry writes KDERIV = 1.5 (000:12755), so it is not held to
whole numbers. Columns are those of the value, counted by hand from 1.

A number that names one thing is held the same way where its range prints no decimal part: CAMSTART and
CAMEND name a cam segment (000:7807-7810, ranges 1 ≤ x ≤ 65535: 000:7778, 7889), MASTERCHANNEL the channel
of the master (000:13779, 0 ≤ x ≤ 11: 000:13799), and FOLLOWDENOM is the denominator that keeps a follow ratio
free of fractions (000:10802-10804, 1 ≤ x ≤ 128: 000:10798). MOVEBUFFERSIZE counts the moves the buffer
stores, "between 2 and 100" (000:11053-11054), as MintMT's row holds it.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.runtime.interpreter.vm import StopReason
from tests.analysis.placed import placed_codes
from tests.runtime.running import simulate

_FRACTIONS = [
    pytest.param("CONFIG.0 = 0.5\n", 12, id="CONFIG"),
    pytest.param("FOLLOWMODE.0 = 0.5\n", 16, id="FOLLOWMODE"),
    pytest.param("CAM.0 = 0.5\n", 9, id="CAM"),
    pytest.param("BANK = 0.5\n", 8, id="BANK"),
    pytest.param("STOPINPUTMODE.0 = 1.5\n", 19, id="STOPINPUTMODE"),
    pytest.param("ADCMODE.0 = 0.5\n", 13, id="ADCMODE"),
    pytest.param("CONFIG.0 = _cfSERVO / 2\n", 12, id="a constant expression"),
]


@pytest.mark.parametrize(("source", "column"), _FRACTIONS)
def test_mint_check_reports_error_3_at_the_fraction_and_mint_run_stops_on_it(source: str, column: int) -> None:
    assert placed_codes(source) == [("E0003", 1, column)]
    result = simulate(source, controller="nextmove-pci")  # the controller mint check takes by default
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 3, 1)


@pytest.mark.parametrize(
    "source",
    [
        pytest.param("CONFIG.0 = _cfSERVO\nFOLLOWMODE.0 = 1.0\nSTOPINPUTMODE.0 = 2\n", id="whole modes"),
        pytest.param("KDERIV.0 = 1.5\n", id="a gain, as the guide writes it"),
    ],
)
def test_whole_modes_and_fractional_gains_pass_both_tools(source: str) -> None:
    assert placed_codes(source) == []
    # the drives as at power-up: disabled, as CONFIG needs them (000:8481)
    assert simulate(source, controller="nextmove-pci", enable=False).stop.reason is StopReason.END


@pytest.mark.parametrize(
    ("source", "controller", "column"),
    [
        pytest.param("CAMSTART.0 = 1.5\n", "nextmove-pci", 14, id="CAMSTART"),
        pytest.param("CAMEND.0 = 2.5\n", "nextmove-pci", 12, id="CAMEND"),
        pytest.param("MASTERCHANNEL.1 = 0.5\n", "nextmove-pci", 19, id="MASTERCHANNEL"),
        pytest.param("FOLLOWDENOM.0 = 1.5\n", "mintdrive", 17, id="FOLLOWDENOM"),
        pytest.param("MOVEBUFFERSIZE.0 = 2.5\n", "nextmove-pci", 20, id="MOVEBUFFERSIZE"),
    ],
)
def test_a_fraction_naming_a_segment_channel_denominator_or_count_is_error_3_in_both_tools(
    source: str, controller: str, column: int
) -> None:
    index = mintlang.LineIndex(source)
    found = [(d.code, index.position(d.span.start).column) for d in mintlang.check(source, controller=controller)]
    assert found == [("E0003", column)]
    result = simulate(source, controller=controller)
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 3, 1)
