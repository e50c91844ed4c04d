"""The events rule (``mintlang/analysis/rules/events.py``): the complete list of diagnostics each small
program gets, as (code, severity, line); line numbers in comments refer to the Mint v4 guide (000_*)."""

from __future__ import annotations

import mintlang
from tests.analysis.checking import ERROR, WARNING, found


def test_fastin_and_fastinx_together_are_error_3006() -> None:
    # line 19108: #3006 #FASTIN conflicts with #FASTINx
    assert found("END\n#FASTIN\nRETURN\n#FASTIN2\nRETURN\n") == [("E3006", ERROR, 4)]


def test_an_input_handler_for_an_input_the_controller_lacks_is_a_warning() -> None:
    # NextMove BX has digital inputs 0 to 15 (line 5613)
    assert found("END\n#IN20\nRETURN\n", controller="nextmove-bx") == [("W109", WARNING, 2)]
    assert found("END\n#IN15\nRETURN\n", controller="nextmove-bx") == []


def test_a_mint_v3_input_handler_past_input_7_is_a_warning() -> None:
    # Mint v3 has an interrupt routine for each of the 8 user inputs, #IN0 to #IN7 (001:2523-2527): #IN8 is a
    # plain label nothing calls, on any controller of the v3 guide (mint-run --dialect v3 never calls it)
    v3 = [(d.code, d.message) for d in mintlang.check("END\n#IN8\nRETURN\n#in7\nRETURN\n", dialect="v3")]
    assert v3 == [("W109", "#IN8: Mint v3 calls #IN0 to #IN7 only, one for each user input, so this is never called")]


def test_a_mint_v3_fast_interrupt_handler_with_a_number_is_a_warning() -> None:
    # Mint v3 has one fast interrupt and calls #FASTPOS on it (001:2585-2587): #FASTPOS1 is a plain label
    v3 = [(d.code, d.message) for d in mintlang.check("END\n#FASTPOS1\nRETURN\n#fastpos\nRETURN\n", dialect="v3")]
    never = "Mint v3 calls #FASTPOS alone, on its one fast interrupt, so this is never called"
    assert v3 == [("W109", f"#FASTPOS1: {never}")]


def test_only_comms_locations_one_to_five_raise_an_event() -> None:
    # line 1898: #COMMS1 .. #COMMS5
    assert found("END\n#COMMS6\nRETURN\n") == [("W109", WARNING, 2)]
    assert found("END\n#COMMS5\nRETURN\n") == []
