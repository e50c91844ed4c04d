"""S-TERM: a TERMINAL that names the LCD tells the user to give the keypadNode's node.

v3 ``TERM = _lcd`` (1) and ``_both`` (3) sent output to the keypad/display on the controller's own
bus (001:11989-12020). v4 ``_tmLCD1`` is a CAN keypadNode (000:16698) that a program reaches only once
``KEYPADNODE._tmLCD1 = <node>`` names it, as the v4 guide's example does before its ``TERMINAL``
(000:2073-2078); the migration spec says so under S-TERM and lists ``TERM = _lcd`` under X-KEYPAD.
The node number is the plant's, so the rewrite stays and a manual item asks for it. The programs run on
NextMove BX, which has the RS232 port (000:16693-16697): on the PC cards a serial terminal gets an item of its
own (test_a_serial_terminal_the_controller_lacks_is_flagged).
"""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate

KEYPAD = "the v3 LCD is a CAN keypadNode in v4: give its node with KEYPADNODE._tmLCD1 = <node> (v4 guide section 3.9)"


@pytest.mark.parametrize("source", ["TERM = _lcd\n", "TM = 3\n"], ids=["the LCD", "both"])
def test_the_lcd_asks_for_its_keypad_node(source: str) -> None:
    result = migrate(source, only=["S-TERM"], controller="nextmove-bx")
    assert [(item.line, item.rule, item.reason) for item in result.manual] == [(2, "S-TERM", KEYPAD)]


def test_the_serial_port_alone_needs_no_node() -> None:
    result = migrate("TERM = _serial\n", only=["S-TERM"], controller="nextmove-bx")
    assert (result.text, result.manual) == ("TERMINAL = _tmRS232\n", ())
