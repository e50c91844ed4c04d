"""A ``#COMMS1`` handler that leaves by ``GOTO`` stays a v4 handler.

In v4 a handler may ``GOTO`` another label and return from there: that label's ``RETURN`` ends the handler
(a ``RETURN`` goes back to where the event or ``GOSUB`` was called, 000:1841-1870; the guide warns only against
leaving a handler without one, 000:11199-11215). MT-20 (mintlang/MINTMT.md) makes ``#COMMS1`` … ``RETURN`` an
``Event Comms1`` … ``End Event`` only when the two say the same: an ``Event`` block ends only at its
``End Event`` (002:82-84), so the ``GOTO`` left it open and the other label's ``RETURN`` was one without
``GOSUB``, error 2010 in the migrated program of a valid v4 one.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.migrate.mintmt import to_mintmt

REASON = "a GOTO leaves it for a label whose RETURN ends it in v4; an Event block ends only at End Event"
KEPT = f"REM MIGRATE: MT-EVENT: #COMMS1 is kept as a v4 handler: {REASON}"
SUB = "REM MIGRATE: MT-EVENT: #big is kept as v4 writes it: the notes show no MintMT subroutine"


@pytest.mark.parametrize(
    ("v4", "mintmt"),
    [
        pytest.param(
            "DIM v\nEND\n#COMMS1\nv = COMMS(1)\nIF v > 2 THEN GOTO big\nRETURN\n#big\nv = 0\nRETURN\n",
            f"DIM v\nEND\n{KEPT}\n#COMMS1\nv = COMMS(1)\nIF v > 2 THEN GOTO big\nRETURN\n{SUB}\n#big\nv = 0\nRETURN\n",
            id="goto-in-a-one-line-if",
        ),
        pytest.param(
            "DIM v\nEND\n#COMMS1\nv = COMMS(1)\nGOTO big\nRETURN\n#big\nv = 0\nRETURN\n",
            f"DIM v\nEND\n{KEPT}\n#COMMS1\nv = COMMS(1)\nGOTO big\nRETURN\n{SUB}\n#big\nv = 0\nRETURN\n",
            id="goto-alone",
        ),
    ],
)
def test_a_goto_out_of_the_handler_keeps_it_and_flags_it(v4: str, mintmt: str) -> None:
    assert [d for d in mintlang.check_application(v4).program if d.code[0] == "E"] == []
    result = to_mintmt(v4)
    assert result.text == mintmt
    assert [(item.rule, item.original_line) for item in result.manual] == [("MT-EVENT", 3), ("MT-EVENT", 7)]
    errors = [d for d in mintlang.check_application(result.text, dialect="mintmt").program if d.code[0] == "E"]
    assert errors == []


def test_a_gosub_from_the_handler_comes_back_into_it() -> None:
    v4 = "DIM v\nEND\n#COMMS1\nGOSUB big\nRETURN\n#big\nv = 0\nRETURN\n"
    result = to_mintmt(v4)
    assert result.text == f"DIM v\nEND\nEVENT COMMS1\nGOSUB big\nEND EVENT\n{SUB}\n#big\nv = 0\nRETURN\n"
