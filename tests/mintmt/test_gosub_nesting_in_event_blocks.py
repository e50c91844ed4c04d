"""W115 (a routine called again before it returns) in MintMT reads an ``Event`` block as a routine of its own.

Each GOSUB nests one level until its RETURN (000:11169, 000:19033-19036). An ``Event Comms2`` … ``End Event`` block
(002:82-84) is the handler of its event, not part of the labelled routine written above it: its calls
were counted as that routine's, so a handler kept as v4's ``#COMMS1`` and called from the block read
as calling itself, and a routine calling itself, reached only from the block, went unreported.
"""

from __future__ import annotations

import mintlang


def _w115(source: str) -> list[tuple[int, str]]:
    found = mintlang.check_application(source, dialect="mintmt").program
    return [(source.count("\n", 0, d.span.start) + 1, d.message) for d in found if d.code == "W115"]


def test_a_call_from_an_event_block_is_not_a_call_from_the_label_above_it() -> None:
    source = 'Loop\n  PAUSE IN(1)\nEnd Loop\n#COMMS1\n  PRINT "one"\nRETURN\nEvent Comms2\n  GOSUB COMMS1\nEnd Event\n'
    assert _w115(source) == []


def test_a_routine_calling_itself_reached_from_an_event_block_is_reported() -> None:
    """``#again`` calls itself on line 5; only the block of line 7 calls it."""
    source = "Loop\n  GO(0)\nEnd Loop\n#again\n  GOSUB again\nRETURN\nEvent Comms1\n  GOSUB again\nEnd Event\n"
    assert _w115(source) == [(5, "#again is called again before it returns: every call nests deeper")]
