"""Hover says where a range holds a keyword's value times its scale factor: the guide prints a Scaled keyword's
range for the value multiplied by the scale factor (000:5647-5649), so POS's ±8388607 bounds counts, not the user
units a program writes after ``SCALE = 2000``; KPROP, not scaled, is ranged as written."""

from __future__ import annotations

from mintlang.lsp.features.hover import hover_text
from mintlang.lsp.workspace import Analyses, Settings


def _hover(text: str) -> str:
    analyses = Analyses(read=lambda _: None, settings=Settings.from_options({"controller": "nextmove-bx"}))
    shown = hover_text(analyses.snapshot("file:///scaled.mnt", text, 1), 0)
    assert shown is not None
    return shown[0]


def test_a_scaled_keywords_range_is_of_the_value_times_its_scale_factor() -> None:
    # 000:15110-15111: POS's row ticks Scaled, range -8388607.0 ≤ x ≤ 8388607.0
    assert "- Range: -8388607.0 ≤ x ≤ 8388607.0, of the value times its scale factor\n" in _hover("POS.0 = 1\n")


def test_an_unscaled_keywords_range_is_of_the_value() -> None:
    shown = _hover("KPROP.0 = 1\n")
    assert "- Range: " in shown
    assert "scale factor" not in shown
