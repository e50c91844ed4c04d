"""``#COMMS01`` stays as v4 writes it: only ``#COMMS1`` … ``#COMMS5`` become ``Event Comms1`` … ``Comms5``.

The v4 guide names the handlers ``#COMMS1`` .. ``#COMMS5`` (000:1898, 000:5066-5070) and the comms note
``Event Comms1`` (002:82); neither says whether ``#COMMS01`` names the same event. Rewritten as
``EVENT COMMS1`` it became the handler of comms location 1 in MintMT whatever it was in v4, and
``mint-migrate --verify`` found the two runs diverging. MT-20 rewrites a handler only when the two say the
same; this one is kept and flagged, and MintMT reads the label as v4 does (MT-1).
"""

from __future__ import annotations

import pytest

from mintlang.migrate.mintmt import to_mintmt


@pytest.mark.parametrize(
    ("label", "number"),
    [
        pytest.param("#COMMS01", 1, id="comms01"),
        pytest.param("#comms005", 5, id="comms005"),
    ],
)
def test_a_leading_zero_keeps_the_label_and_flags_it(label: str, number: int) -> None:
    v4 = f"END\n{label}\nJOG.0 = 1\nRETURN\n"
    reason = f"the v4 guide and the notes write COMMS{number}, and say nothing of a leading zero"
    marker = f"REM MIGRATE: MT-EVENT: {label} is kept as a v4 handler: {reason}"
    result = to_mintmt(v4)
    assert result.text == f"END\n{marker}\n{label}\nJOG(0) = 1\nRETURN\n"
    assert [(item.rule, item.original_line) for item in result.manual] == [("MT-EVENT", 2)]


def test_the_name_the_guide_writes_becomes_an_event_block() -> None:
    assert to_mintmt("END\n#COMMS1\nJOG.0 = 1\nRETURN\n").text == "END\nEVENT COMMS1\nJOG(0) = 1\nEND EVENT\n"
