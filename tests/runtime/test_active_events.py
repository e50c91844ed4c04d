"""EVENTACTIVE reads which event handlers are running, in the bits EVENTDISABLE and EVENTPENDING use.

The guide: EVENTACTIVE shows which events are active, beside EVENTPENDING, which takes the same bit
pattern as EVENTDISABLE: 1 error, 6 timer (000:4355-4392); the quick reference reads it on NextMove only
(000:18061). A handler pre-empted by a higher one (#ONERROR interrupting #TIMER, 000:4320-4322) is still
active. Its keyword is read only: the quick reference reads it, and nothing in the guide writes it.
"""

from __future__ import annotations

from tests.runtime.running import simulate

PROGRAM = """DIM a
PRINT EVENTACTIVE
TIMEREVENT = 10 : PAUSE a
PRINT EVENTACTIVE
END
#TIMER
TIMEREVENT = 0
PRINT EVENTACTIVE
EVENTPENDING = 2
PRINT EVENTACTIVE
a = 1
RETURN
#ONERROR
PRINT EVENTACTIVE
RETURN
"""


def test_each_running_handler_shows_its_bit_and_a_pre_empted_one_stays_active() -> None:
    # program 0; #TIMER 64 (bit 6); #ONERROR forced inside it 2 + 64; back in #TIMER 64; after both 0
    assert simulate(PROGRAM, controller="nextmove-pci").terminal == "0\n64\n66\n64\n0\n"


def test_eventactive_is_read_only() -> None:
    result = simulate('EVENTACTIVE = 0\nEND\n#ONERROR\nPRINT "ERR ", ERR\nRETURN\n', controller="nextmove-pci")
    # an interpreter error: #ONERROR sees it, and the program ends when it returns (000:4614-4619)
    assert result.terminal == "ERR 2000\nR2000: PROGRAM Read only or Command [line 1]\n"


def test_mintdrive_has_no_eventactive() -> None:
    # its controllers are the NextMoves (000:18061): elsewhere the keyword is not supported, error 17
    result = simulate('PRINT EVENTACTIVE\nEND\n#ONERROR\nPRINT "ERR ", ERR\nRETURN\n', controller="mintdrive")
    assert result.terminal == "ERR 17\n"
