"""An output-selecting keyword takes a channel number in its controller's span or a relay constant.

DRIVEENABLEOUTPUT (000:9326-9338) and GLOBALERROROUTPUT (000:10976-10985) print their range as
"-1 ≤ x ≤ 11 and relay constant(s)" on NextMove PC and PCI and "-1 ≤ x ≤ 7 ..." on NextMove BX;
their value tables give the relay constants 1000, 1001 and 1002 (_RELAY0-_RELAY2, 000:9362-9366,
11007-11011), the last two the relays of the expansion cards, marked "(NextMove PCI only)" (000:9365,
9368, 11010, 11013). The NextMove PCI label carries a footnote: two expansion cards raise the span to 35
(000:9388-9389, 11030-11031), and the checker assumes both are fitted. Any other value is MML
error 3 (000:18518).
"""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import mintlang


def _codes(source: str, controller: str) -> list[str]:
    return [d.code for d in mintlang.check(source, controller=controller)]


@pytest.mark.parametrize("keyword", ["DRIVEENABLEOUTPUT.0", "GLOBALERROROUTPUT"])
@pytest.mark.parametrize(
    ("controller", "value"),
    [
        ("nextmove-pc", "-1"),
        ("nextmove-pc", "11"),
        ("nextmove-pc", "_RELAY0"),
        ("nextmove-bx", "7"),
        ("nextmove-bx", "1000"),
        ("nextmove-pci", "35"),
        ("nextmove-pci", "_RELAY2"),
    ],
)
def test_a_channel_in_the_span_or_a_relay_is_accepted(keyword: str, controller: str, value: str) -> None:
    assert _codes(f"{keyword} = {value}\n", controller) == []


@pytest.mark.parametrize("keyword", ["DRIVEENABLEOUTPUT.0", "GLOBALERROROUTPUT"])
@pytest.mark.parametrize(
    ("controller", "value"),
    [
        ("nextmove-pc", "-2"),
        ("nextmove-pc", "12"),
        ("nextmove-pc", "999"),
        ("nextmove-bx", "8"),
        ("nextmove-pci", "36"),
        ("nextmove-pci", "999"),
        ("nextmove-pci", "1003"),
    ],
)
def test_any_other_value_is_error_3(keyword: str, controller: str, value: str) -> None:
    assert _codes(f"{keyword} = {value}\n", controller) == ["E0003"]


@pytest.mark.parametrize(
    ("source", "controller"),
    [
        pytest.param("DRIVEENABLEOUTPUT.0 = _RELAY1\n", "nextmove-pc", id="drive-enable-relay1-pc"),
        pytest.param("DRIVEENABLEOUTPUT.0 = 1002\n", "nextmove-pc", id="drive-enable-relay2-pc"),
        pytest.param("DRIVEENABLEOUTPUT.0 = _RELAY1\n", "nextmove-bx", id="drive-enable-relay1-bx"),
        pytest.param("DRIVEENABLEOUTPUT.0 = _RELAY2\n", "servonode51", id="drive-enable-relay2-servonode"),
        pytest.param("GLOBALERROROUTPUT = _RELAY2\n", "nextmove-pc", id="global-error-relay2-pc"),
        pytest.param("GLOBALERROROUTPUT = 1001\n", "nextmove-bx", id="global-error-relay1-bx"),
    ],
)
def test_an_expansion_card_relay_off_nextmove_pci_is_error_3(source: str, controller: str) -> None:
    # _RELAY1 and _RELAY2 are the relays of the expansion cards, "(NextMove PCI only)" (000:9362-9368, 11007-11013)
    (diagnostic,) = mintlang.check(source, controller=controller)
    assert diagnostic.code == "E0003"
    assert "NextMove PCI only" in diagnostic.message


@pytest.mark.parametrize("keyword", ["ERRORINPUT", "LIMITFORWARDINPUT", "LIMITREVERSEINPUT"])
def test_an_input_span_widens_on_nextmove_pci_with_expansion_cards(keyword: str) -> None:
    # The bare card's span is -1 to 19; its footnote raises it to 59 with two expansion cards
    # (000:10041 with 10078-10079, 13408 with 13435-13436, 13593 with 13624-13625).
    assert _codes(f"{keyword}.0 = 59\n", "nextmove-pci") == []
    assert _codes(f"{keyword}.0 = 60\n", "nextmove-pci") == ["E0003"]
    assert _codes(f"{keyword}.0 = 24\n", "nextmove-pc") == ["E0003"]  # the PC's own row stops at 23


@settings(max_examples=60, deadline=None)
@given(value=st.integers(min_value=-50, max_value=1100))
def test_on_nextmove_pc_exactly_the_span_and_the_main_card_relay_pass(value: int) -> None:
    accepted = -1 <= value <= 11 or value == 1000
    assert _codes(f"DRIVEENABLEOUTPUT.0 = {value}\n", "nextmove-pc") == ([] if accepted else ["E0003"])
