"""A NextMove PCI with its two expansion cards: channels numbered across the cards, BANK for the rest.

Each expansion card has the main card's 20 inputs, 12 outputs and a relay (000:7340-7342,
9388-9389); its channels follow the main card's, inputs 20 to 59 and outputs 12 to 35
(000:4076-4078, 4125-4127), so ``IN.21`` is input 1 of card 1 whatever BANK says. The keywords
that read or write a whole card (IN, OUT, IMASK, INPUTACTIVELEVEL, RELAY …) address the bank
BANK selects, 0 to 2, the main card by default (000:7316-7375). ``mint check`` accepts the cards'
channels, and ``mint-run`` fits both cards, so the guide's examples that use them run. Values are
worked out by hand from the guide's bit patterns.
"""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.io_banks import IOBanks
from mintlang.runtime.scenario import InputLevel, Scenario
from tests.runtime.running import simulate

# The guide's BANK example (000:7367-7372), printing what it set and read.
_GUIDE_EXAMPLE = """DIM inputPattern=0
BANK = 0 : REM set I/O to main card
OUT = 0x31 : REM write to digital outputs on main card
BANK = 1 : REM set I/O to expansion card 1
OUT = 0xFF : REM write to digital outputs on exp card 1
inputPattern = IN : REM read digital inputs on exp card 1
PRINT inputPattern, " ", OUT, " ", OUT.12, " ", OUT.19, " ", OUT.20
BANK = 0
PRINT OUT
"""


def test_the_guides_bank_example_writes_each_cards_outputs_and_reads_card_1s_inputs() -> None:
    inputs = Scenario(inputs=(InputLevel(0, 21, 1), InputLevel(0, 3, 1)))  # input 1 of card 1; input 3 of the main card
    result = simulate(_GUIDE_EXAMPLE, controller="nextmove-pci", scenario=inputs)
    assert result.stop.reason is StopReason.END
    # card 1: IN is 2 (its input 1), OUT 255 (outputs 12-19 on, 20 off); then the main card's 0x31 = 49
    assert result.terminal == "2 255 1 1 0\n49\n"
    assert result.outputs == 0x31 | 0xFF << 12  # outputs 0, 4, 5 and 12 to 19, numbered across the cards


@pytest.mark.parametrize("bank", [0, 1, 2])
def test_a_channel_is_numbered_across_the_cards_whatever_the_bank(bank: int) -> None:
    inputs = Scenario(inputs=(InputLevel(0, 45, 1),))  # input 5 of card 2
    result = simulate(
        f"BANK = {bank}\nOUT.30 = 1\nPRINT IN.45, IN.5, IN.25\n", controller="nextmove-pci", scenario=inputs
    )
    assert (result.terminal, result.outputs) == ("100\n", 1 << 30)


def test_the_guides_timer_example_reads_card_1s_inputs() -> None:
    program = """TIMEREVENT = 50
PAUSE TIME > 200
END
#TIMER
IF IN21 THEN PRINT "Air supply failed" : TIMEREVENT = 0
RETURN
"""
    inputs = Scenario(inputs=(InputLevel(120, 21, 1),))
    result = simulate(program, controller="nextmove-pci", scenario=inputs)
    assert result.terminal == "Air supply failed\n"


@pytest.mark.parametrize("bank", [0, 1, 2])
def test_each_card_starts_as_the_keyword_tables_say_a_card_does(bank: int) -> None:
    # IMASK and INPUTACTIVELEVEL default to the card's 20 inputs, 1048575 (000:11896, 12281)
    result = simulate(f'BANK = {bank}\nPRINT IMASK, " ", INPUTACTIVELEVEL, " ", OUT\n', controller="nextmove-pci")
    assert result.terminal == "1048575 1048575 0\n"


@pytest.mark.parametrize(
    ("statement", "code"),
    [
        pytest.param("BANK = 3", 3, id="no-third-card"),  # BANK's range is 0 to 2 (000:7337)
        pytest.param("BANK = 1\nOUT = 4096", 3, id="a-whole-card-is-12-outputs"),  # OUT x < 4096 (000:14908-14913)
        pytest.param("PRINT IN.60", 7, id="past-the-second-card"),  # inputs end at 59 (000:4078)
        pytest.param("OUT.36 = 1", 8, id="past-the-second-cards-outputs"),  # outputs end at 35 (000:4126-4127)
    ],
)
def test_what_no_card_holds_is_the_controllers_error(statement: str, code: int) -> None:
    result = simulate(statement + "\n", controller="nextmove-pci")
    assert (result.stop.reason, result.err) == (StopReason.ERROR, code)


def test_relay_addresses_the_selected_cards_relay() -> None:
    # each card has a relay (000:9388-9389); RELAY takes the bank BANK selects (000:7363)
    result = simulate("BANK = 2\nRELAY = 1\nBANK = 0\nPRINT RELAY\nBANK = 2\nPRINT RELAY\n", controller="nextmove-pci")
    assert result.terminal == "0\n1\n"
    assert result.relay == 0b100


def test_a_drive_enabled_by_an_expansion_cards_relay_drives_that_relay() -> None:
    # _RELAY1 is 1001, the relay of expansion card 1 (000:9363-9366)
    result = simulate("DRIVEENABLEOUTPUT.0 = _RELAY1\nDRIVEENABLE.0 = 1\n", controller="nextmove-pci", enable=False)
    assert result.relay == 0b010


def test_an_input_event_of_a_card_runs_its_handler() -> None:
    # #IN0..#IN19 on the main card, to #IN59 with two cards (000:5958-5959)
    program = 'PAUSE TIME > 100\nEND\n#IN42\nPRINT "card 2"\nBANK = 2 : IMASK = 0\nRETURN\n'
    result = simulate(program, controller="nextmove-pci", scenario=Scenario(inputs=(InputLevel(50, 42, 1),)))
    assert result.terminal == "card 2\n"


@given(
    banks=st.integers(min_value=1, max_value=3),
    width=st.integers(min_value=1, max_value=24),
    bits=st.integers(min_value=0, max_value=(1 << 72) - 1),
    data=st.data(),
)
def test_writing_one_banks_word_reads_back_and_leaves_the_others(banks: int, width: int, bits: int, data) -> None:
    layout = IOBanks(banks, width, width)
    bits &= (1 << banks * width) - 1
    bank = data.draw(st.integers(min_value=0, max_value=banks - 1))
    word = data.draw(st.integers(min_value=0, max_value=(1 << width) - 1))
    written = layout.with_output_word(bits, bank, word)
    assert layout.output_word(written, bank) == word
    others = [other for other in range(banks) if other != bank]
    assert [layout.output_word(written, other) for other in others] == [
        layout.output_word(bits, other) for other in others
    ]
