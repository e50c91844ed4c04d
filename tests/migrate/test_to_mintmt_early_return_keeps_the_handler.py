"""A ``#COMMS1`` handler that returns early, from inside one of its blocks, stays a v4 handler.

MT-20 (mintlang/MINTMT.md) makes ``#COMMS1`` … ``RETURN`` an ``Event Comms1`` … ``End Event`` only when
one ``RETURN`` alone on its line ends the handler. A ``RETURN`` inside a block IF (``IF … DO`` …
``ENDIF``, 000:1594-1600) or a ``LOOP`` returns early: turned into ``End Event`` it closed the event
inside its ``If`` and left the handler's last ``RETURN`` in the main program.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.migrate.mintmt import to_mintmt

REASON = "it does not end with one RETURN alone on its line before the next label"
KEPT = f"REM MIGRATE: MT-EVENT: #COMMS1 is kept as a v4 handler: {REASON}"


@pytest.mark.parametrize(
    ("v4", "mintmt"),
    [
        pytest.param(
            "DIM a\nEND\n#COMMS1\nIF a DO\nRETURN\nENDIF\nJOG.0 = 1\nRETURN\n",
            f"DIM a\nEND\n{KEPT}\n#COMMS1\nIF a THEN\nRETURN\nEND IF\nJOG(0) = 1\nRETURN\n",
            id="early-return-in-an-if-block",
        ),
        pytest.param(
            "DIM a\nEND\n#COMMS1\nLOOP\nIF a DO\nRETURN\nENDIF\nENDL\n",
            f"DIM a\nEND\n{KEPT}\n#COMMS1\nLOOP\nIF a THEN\nRETURN\nEND IF\nEND LOOP\n",
            id="only-return-in-a-loop",
        ),
    ],
)
def test_a_return_inside_a_block_keeps_the_handler_and_flags_it(v4: str, mintmt: str) -> None:
    result = to_mintmt(v4)
    assert result.text == mintmt
    assert [(item.rule, item.original_line) for item in result.manual] == [("MT-EVENT", 3)]
    errors = [d for d in mintlang.check_application(result.text, dialect="mintmt").program if d.code[0] == "E"]
    assert errors == []
