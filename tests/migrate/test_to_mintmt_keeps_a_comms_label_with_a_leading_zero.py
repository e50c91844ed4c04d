"""``#COMMS01`` stays as v4 writes it: only ``#COMMS1`` … ``#COMMS5`` become ``Event Comms1`` … ``Comms5``.

The v4 guide names the handlers ``#COMMS1`` .. ``#COMMS5`` (000:1898, 000:5066-5070) and the comms note
``Event Comms1`` (002:82). A number with a leading zero is no event number (``mintlang.semantic.events``):
``#COMMS01`` is a plain label in v4, which ``mint-run`` never calls for the comms array. Rewritten as
``EVENT COMMS1`` it became the handler of comms location 1 in MintMT, and ``mint-migrate --verify`` found
the two runs diverging. It is kept and flagged as every other label is, and MintMT reads it as v4 does (MT-1).
"""

from __future__ import annotations

import pytest

from mintlang.migrate.mintmt import to_mintmt


@pytest.mark.parametrize("label", [pytest.param("#COMMS01", id="comms01"), pytest.param("#comms005", id="comms005")])
def test_a_leading_zero_keeps_the_label_and_flags_it(label: str) -> None:
    v4 = f"END\n{label}\nJOG.0 = 1\nRETURN\n"
    marker = f"REM MIGRATE: MT-EVENT: {label} is kept as v4 writes it: the notes show no MintMT subroutine"
    result = to_mintmt(v4)
    assert result.text == f"END\n{marker}\n{label}\nJOG(0) = 1\nRETURN\n"
    assert [(item.rule, item.original_line) for item in result.manual] == [("MT-EVENT", 2)]


def test_the_name_the_guide_writes_becomes_an_event_block() -> None:
    assert to_mintmt("END\n#COMMS1\nJOG.0 = 1\nRETURN\n").text == "END\nEVENT COMMS1\nJOG(0) = 1\nEND EVENT\n"
