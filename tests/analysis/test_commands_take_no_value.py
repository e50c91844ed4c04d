"""Error 2000 for a value given to a command the manual prints no attribute table for.

Chapter 12 defines #2000 as writing a value to a keyword that is read only *or is a command*
(000:18905-18908). BEEP, CLS, BOL, TRON, TROFF, VER, LINE, LOCATE and RUN have entries whose
only formats are the bare command (000:7377-7392 BEEP, 000:17154-17166 VER, ...), so no
format gives them a value; neither does any attribute table, so the verdict rests on the formats.
"""

from __future__ import annotations

import pytest

import mintlang


def _codes(source: str) -> list[tuple[str, int]]:
    index = mintlang.LineIndex(source)
    return [(d.code, index.position(d.span.start).line) for d in mintlang.check(source)]


@pytest.mark.parametrize(
    "source",
    [
        pytest.param("BEEP = 1\n", id="BEEP"),
        pytest.param("CLS = 0\n", id="CLS"),
        pytest.param("BOL = 1\n", id="BOL"),
        pytest.param("TRON = 1\n", id="TRON"),
        pytest.param("TROFF = 0\n", id="TROFF"),
        pytest.param("VER = 4\n", id="VER"),
        pytest.param("LOCATE = 1\n", id="LOCATE"),
        pytest.param("RUN = 1\n", id="RUN"),
    ],
)
def test_a_command_given_a_value_is_error_2000(source: str) -> None:
    assert _codes(source) == [("E2000", 1)]


def test_the_message_names_the_command() -> None:
    (diagnostic,) = mintlang.check("PRINT 1\nBEEP = 1\n")
    assert "BEEP is a command" in diagnostic.message
    assert (diagnostic.span.start, diagnostic.span.end) == (8, 12)  # the word BEEP on line 2


@pytest.mark.parametrize(
    "source",
    [
        pytest.param("BEEP\n", id="BEEP-alone"),
        pytest.param("CLS\n", id="CLS-alone"),
        pytest.param("LOOP\nBOL : PRINT POS.0,\nENDL\n", id="BOL-entry-example"),  # 000:7418-7422
        pytest.param("TRON\nTROFF\n", id="TRON-TROFF"),
        pytest.param("LOCATE 1, 2\n", id="LOCATE-operands"),
        pytest.param("PRINT LASTERR\n", id="LASTERR-read"),  # it returns the last error (000:13270-13272)
        pytest.param("DIM v = ERR\nPRINT v\n", id="read-only-read"),
    ],
)
def test_the_manual_forms_stay_clean(source: str) -> None:
    assert _codes(source) == []


def test_a_read_only_keyword_without_a_table_is_still_error_2000() -> None:
    # ERR's only format reads it (v = ERR, 000:9891-9899)
    assert _codes("ERR = 0\n") == [("E2000", 1)]
