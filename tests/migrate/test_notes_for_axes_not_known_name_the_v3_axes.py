"""A note whose axes cannot be known names the axes a v3 controller had, not every axis of the target.

"MINT only supports the control of 3 axes on one controller" (001:782): a v3 program with a #STOP
handler and no move it names the axes of relied on the stop input of axes 0 to 2 at most (001:2508-2521),
so the note asks for STOPINPUT there, not on the twelve axes of a NextMove PCI (000:5613).
"""

from __future__ import annotations

from tests.migrate.helpers import one_rule


def _notes(source: str, controller: str) -> list[str]:
    result = one_rule("S-PROLOGUE", source, controller=controller)
    return [item.reason for item in result.manual if item.rule == "S-PROLOGUE"]


def test_a_stop_handler_without_moves_asks_for_the_stop_input_of_the_three_v3_axes() -> None:
    assert _notes("#STOP\nRETURN\n", "nextmove-pci") == ["STOPINPUT[0,1,2] = <input>; : REM v3 had a stop input"]


def test_a_smaller_target_keeps_its_own_axes() -> None:
    assert _notes("#STOP\nRETURN\n", "mintdrive") == ["STOPINPUT[0] = <input>; : REM v3 had a stop input"]
