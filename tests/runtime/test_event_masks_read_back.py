"""The event masks read back the bits written to them, handlers the run does not call included.

EVENTDISABLE takes 0 to 511 and each set bit stops its handler being called (000:10137, 000:10140);
bit 0 is NextMove PCI's serial event (000:10146), which the simulation never raises, and MintDrive's
HANDLERDISABLE (0 to 383, 000:11290) has bit 7 reserved (000:11306). IPEND sets or clears each
input's bit "even if ... no corresponding #IN0 .. #INx subroutine has been defined", and a bit once
set "will remain set until cleared" (000:12616, 000:12621-12623).
"""

from __future__ import annotations

import pytest

from tests.runtime.running import simulate


@pytest.mark.parametrize(
    ("controller", "keyword", "value"),
    [
        pytest.param("nextmove-pci", "EVENTDISABLE", 511, id="every NextMove handler"),
        pytest.param("nextmove-pci", "EVENTDISABLE", 1, id="NextMove PCI serial event"),
        pytest.param("mintdrive", "HANDLERDISABLE", 128, id="MintDrive reserved bit"),
    ],
)
def test_a_disable_mask_reads_back_what_was_written(controller: str, keyword: str, value: int) -> None:
    source = f"{keyword} = {value}\nPRINT {keyword}\n"
    assert simulate(source, controller=controller).terminal == f"{value}\n"


def test_ipend_bits_without_handlers_stay_set_until_written_clear() -> None:
    # inputs 0 and 2 set (5); nothing calls them, so after 5 ms they still read 5; clearing bit 2 leaves 1
    source = "IPEND = 5\nWAIT = 5\nPRINT IPEND\nIPEND = IPEND & 0xFFFB\nWAIT = 5\nPRINT IPEND\n"
    assert simulate(source).terminal == "5\n1\n"


def test_ipend_calls_the_handlers_there_are_and_keeps_the_other_bits() -> None:
    # #IN0 runs and its bit clears (000:12616); input 2 has no handler, so its bit stays (4)
    source = 'DIM n\nIPEND = 5\nWAIT = 5\nPRINT n, " ", IPEND\nEND\n#IN0\nn = n + 1\nRETURN\n'
    assert simulate(source).terminal == "1 4\n"
