"""S-PROLOGUE: a program that moves relied on v3's stop input, whether it names it or not.

The v3 guide lists a "Stop input to bring all axes to a controlled stop" among the controller's safety
features (001:751-758), and "The STOP input is used to halt motion on all axes", wired to the guard as
"a safety requirement" (001:4544-4546), with no keyword needed; #STOP, STOPSW and STOPMODE only add to
it (001:4548-4558). v4 user I/O has no default assignment (000:4058-4061): an
input stops motion only once STOPINPUT names it. So a migrated program that moves gets the STOPINPUT
note beside the limit inputs', as the spec's prologue lists it (S-PROLOGUE); one that never moves, and
has no #STOP handler, needs none.
"""

from __future__ import annotations

from tests.migrate.helpers import one_rule

NOTE = "STOPINPUT[0,1] = <input>; : REM v3 had a stop input"


def _notes(source: str) -> list[str]:
    return [item.reason for item in one_rule("S-PROLOGUE", source).manual if item.rule == "S-PROLOGUE"]


def test_a_program_that_moves_gets_the_stop_input_note() -> None:
    assert NOTE in _notes("AXES[0,1]\nMOVEA = 10,20 : GO\nPAUSE IDLE[0,1]\n")


def test_a_program_that_assigns_it_gets_none() -> None:
    assert NOTE not in _notes("AXES[0,1]\nSTOPINPUT[0,1] = 4;\nJOG = 5,5\n")


def test_a_program_that_never_moves_gets_none() -> None:
    assert _notes("AXES[0,1]\nOUT1 = 1\n") == []
