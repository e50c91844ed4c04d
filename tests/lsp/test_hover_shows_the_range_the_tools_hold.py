"""Hover gives a keyword's range as ``mint check`` and ``mint-run`` hold values to it: where the entry's text
narrows what its table prints, the narrower one (CONTOURMODE: the table prints 0 ≤ x ≤ 3, the text says bit 1
cannot be set without bit 0, so 2 is refused, 000:8643-8654)."""

from __future__ import annotations

from mintlang.lsp.features.hover import hover_text
from mintlang.lsp.workspace import Analyses, Settings


def _hover(text: str) -> str:
    analyses = Analyses(read=lambda _: None, settings=Settings.from_options({}))
    shown = hover_text(analyses.snapshot("file:///range.mnt", text, 1), 0)
    assert shown is not None
    return shown[0]


def test_contourmode_shows_the_modes_bit_1_allows() -> None:
    shown = _hover("CONTOURMODE.0 = 1\n")
    assert "- Range: 0, 1 or 3: bit 1 needs bit 0\n" in shown
    assert "0 ≤ x ≤ 3" not in shown


def test_a_range_the_text_does_not_narrow_is_the_tables() -> None:
    assert "- Range: 1 ≤ x ≤ 8388607\n" in _hover("ACCELTIME.0 = 10\n")
