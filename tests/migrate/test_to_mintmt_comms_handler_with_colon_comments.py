"""A ``#COMMS1`` handler commented as the v4 guide advises still becomes an ``Event Comms1`` block.

The v4 guide says a remark after code should be separated from it by a colon (000:15510-15512:
``PRINT : REM …``). A ``:`` with nothing but a comment after it separates no statement, so
``#COMMS1 : REM …`` is the label alone on its line and ``RETURN : REM …`` the ``RETURN`` alone on its
line (MT-20), as ``#COMMS1 REM …`` and ``RETURN REM …`` already were; so is an ``END : REM …`` or
``ENDL : REM …`` above the handler, which no code runs past. Only the two words are rewritten
(MT-17): the ``:`` and the comment stay, and MintMT reads ``Event Comms1 : ' …`` as it reads
``Event Comms1 ' …``. A statement after the ``:`` still keeps the handler and flags it.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.migrate.mintmt import to_mintmt


@pytest.mark.parametrize(
    ("v4", "mintmt"),
    [
        pytest.param(
            "END\n#COMMS1 : REM host\nJOG.0 = 1\nRETURN\n",
            "END\nEVENT COMMS1 : ' host\nJOG(0) = 1\nEND EVENT\n",
            id="label-colon-comment",
        ),
        pytest.param(
            "END\n#COMMS1\nJOG.0 = 1\nRETURN : REM back\n",
            "END\nEVENT COMMS1\nJOG(0) = 1\nEND EVENT : ' back\n",
            id="return-colon-comment",
        ),
        pytest.param(
            "END : REM stop\n#COMMS2\nJOG.0 = 1\nRETURN\n",
            "END : ' stop\nEVENT COMMS2\nJOG(0) = 1\nEND EVENT\n",
            id="end-colon-comment-above",
        ),
        pytest.param(
            "LOOP\nENDL : REM forever\n#COMMS3:\nJOG.0 = 1\nRETURN:\n",
            "LOOP\nEND LOOP : ' forever\nEVENT COMMS3:\nJOG(0) = 1\nEND EVENT:\n",
            id="endl-colon-comment-above-and-bare-colons",
        ),
    ],
)
def test_a_colon_before_a_comment_keeps_the_handler_an_event(v4: str, mintmt: str) -> None:
    result = to_mintmt(v4)
    assert result.text == mintmt
    assert not result.manual
    assert mintlang.check(result.text, dialect="mintmt") == []


@pytest.mark.parametrize(
    ("v4", "why"),
    [
        pytest.param("END\n#COMMS1 : JOG.0 = 1\nRETURN\n", "a statement follows its label on the line", id="label"),
        pytest.param(
            "END\n#COMMS1\nJOG.0 = 1\nRETURN : JOG.0 = 0\n",
            "it does not end with one RETURN alone on its line before the next label",
            id="return",
        ),
    ],
)
def test_a_statement_after_the_colon_keeps_the_handler(v4: str, why: str) -> None:
    result = to_mintmt(v4)
    assert [(item.rule, item.original_line) for item in result.manual] == [("MT-EVENT", 2)]
    assert result.manual[0].reason == f"#COMMS1 is kept as a v4 handler: {why}"
