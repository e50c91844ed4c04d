"""Hover gives a keyword's access and range as ``mint check`` and ``mint-run`` hold them where the guide prints no
attributes row for the editor's controller, and says the guide prints none: an Advanced-guide entry's (no table),
and ServoNode 51's bit patterns of its own inputs and outputs, whose rows the tables leave out."""

from __future__ import annotations

import pytest

from mintlang.lsp.features.hover import hover_text
from mintlang.lsp.workspace import Analyses, Settings


def _hover(text: str, controller: str) -> str:
    analyses = Analyses(read=lambda _: None, settings=Settings.from_options({"controller": controller}))
    shown = hover_text(analyses.snapshot("file:///word.mnt", text, 1), 0)
    assert shown is not None
    return shown[0]


def test_a_count_of_moves_the_text_bounds_where_no_table_is_printed() -> None:
    # 000:11053-11054: the move buffer stores between 2 and 100 moves per axis; the entry prints no table
    shown = _hover("MOVEBUFFERSIZE.0 = 10\n", "nextmove-bx")
    assert "- Attributes: the guide prints no table: the row mint check and mint-run take\n" in shown
    assert "- Access: read, write\n" in shown
    assert "- Range: 2 ≤ x ≤ 100\n" in shown


def test_a_position_the_text_says_is_read() -> None:
    # 000:11401-11402: HOMEPOS can be read to learn the position before homing set it to zero
    assert "- Access: read\n" in _hover("HOMEPOS.0\n", "nextmove-pci")


@pytest.mark.parametrize(
    ("text", "range_"),
    [
        # 000:4047 and 11932: ServoNode 51 has 6 digital inputs, one bit each (000:12315-12316)
        ("INPUTMODE = 1\n", "0 ≤ x ≤ 63"),
        # 000:4048: and 3 digital outputs, one bit each (OUT = 266 sets outputs 1, 3 and 8: 000:14922-14924)
        ("OUT = 1\n", "0 ≤ x ≤ 7"),
    ],
)
def test_servonode_51s_bit_pattern_of_its_own_inputs_and_outputs(text: str, range_: str) -> None:
    assert f"- Range: {range_}\n" in _hover(text, "servonode51")
