"""A controller label that ends in a footnote number still names its controller.

DRIVEENABLEOUTPUT's attributes table wraps "Nextmove PC," / "NextMove PCI10" onto lines of their
own (000:9328-9332): the 10 is footnote 10, which says two NextMove PCI expansion cards raise the
span to 35 (000:9388-9389). GLOBALERROROUTPUT prints "NextMove PCI13," the same way (000:10978-10982).
"""

from __future__ import annotations

import pytest

from mintlang.keyworddb.model import Controller
from tools.keyworddb.__main__ import DEFAULT_SEEDS
from tools.keyworddb.attributes import parse_attributes
from tools.keyworddb.checkmarks import TICK
from tools.keyworddb.footnotes import expansion_maxima
from tools.keyworddb.seeds import V4_GUIDE, read_seed

_ALL = tuple(Controller)


def _table(*rows: str) -> list[tuple[int, str]]:
    """Numbered table lines, with ``*`` for each tick the PDF text prints."""
    return [(number, row.replace("*", TICK)) for number, row in enumerate(rows, start=1)]


def test_each_controller_of_a_wrapped_footnoted_label_gets_the_row() -> None:
    lines = _table("Nextmove PC, ", "NextMove PCI10 ", "", "* *  *  -1 -1 ≤ x ≤ 11 and relay ", "constant ")
    rows = parse_attributes(lines, _ALL, {})
    assert [row.controllers for row in rows] == [(Controller.NEXTMOVE_PCI, Controller.NEXTMOVE_PC)]
    assert rows[0].default == "-1"


def test_the_footnote_widens_the_span_for_nextmove_pci_only() -> None:
    lines = _table("NextMove PCI13, ", "NextMove PC ", "", "* *    1000 -1 ≤ x ≤ 11 and relay ", "constants ")
    pci, pc = parse_attributes(lines, _ALL, {13: 35.0})
    assert pci.controllers == (Controller.NEXTMOVE_PCI,)
    assert pc.controllers == (Controller.NEXTMOVE_PC,)
    assert pci.range is not None and (pci.range.minimum, pci.range.maximum) == (-1.0, 35.0)
    assert pc.range is not None and (pc.range.minimum, pc.range.maximum) == (-1.0, 11.0)


@pytest.mark.skipif(not (DEFAULT_SEEDS / V4_GUIDE).exists(), reason="the manuals are not here")
def test_the_expansion_card_footnotes_of_the_v4_guide() -> None:
    # 000:5958-5959, 9388-9389, 10078-10079, 11030-11031, 13435-13436, 13624-13625, 14992-14993
    maxima = expansion_maxima(read_seed(DEFAULT_SEEDS / V4_GUIDE))
    assert maxima == {8: 59.0, 10: 35.0, 11: 59.0, 13: 35.0, 14: 59.0, 15: 59.0, 16: 35.0}
