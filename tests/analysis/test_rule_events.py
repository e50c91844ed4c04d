"""The events rule (``mintlang/analysis/rules/events.py``): the complete list of diagnostics each small
program gets, as (code, severity, line); line numbers in comments refer to the Mint v4 guide (000_*)."""

from __future__ import annotations

from tests.analysis.checking import ERROR, WARNING, found


def test_fastin_and_fastinx_together_are_error_3006() -> None:
    # line 19108: #3006 #FASTIN conflicts with #FASTINx
    assert found("END\n#FASTIN\nRETURN\n#FASTIN2\nRETURN\n") == [("E3006", ERROR, 4)]


def test_an_input_handler_for_an_input_the_controller_lacks_is_a_warning() -> None:
    # NextMove BX has digital inputs 0 to 15 (line 5613)
    assert found("END\n#IN20\nRETURN\n", controller="nextmove-bx") == [("W109", WARNING, 2)]
    assert found("END\n#IN15\nRETURN\n", controller="nextmove-bx") == []


def test_only_comms_locations_one_to_five_raise_an_event() -> None:
    # line 1898: #COMMS1 .. #COMMS5
    assert found("END\n#COMMS6\nRETURN\n") == [("W109", WARNING, 2)]
    assert found("END\n#COMMS5\nRETURN\n") == []
