"""Hover gives a keyword's range as ``mint check`` and ``mint-run`` hold it on the editor's controller, where the
entry's table ticks values per controller under one printed row: CONFIG's row prints 0 - 5 for the three NextMoves
(000:8420), its table of motor types ticks off, servo and virtual on NextMove BX, stepper on PCI and PC, PWM on
PC alone, and 4 is reserved (000:8431-8443)."""

from __future__ import annotations

from mintlang.lsp.features.hover import hover_text
from mintlang.lsp.workspace import Analyses, Settings


def _hover(text: str, controller: str) -> str:
    analyses = Analyses(read=lambda _: None, settings=Settings.from_options({"controller": controller}))
    shown = hover_text(analyses.snapshot("file:///config.mnt", text, 1), 0)
    assert shown is not None
    return shown[0]


def test_config_on_nextmove_bx_takes_off_servo_and_virtual() -> None:
    shown = _hover("CONFIG.0 = 1\n", "nextmove-bx")
    assert "- Range: 0, 1, 5\n" in shown
    assert "0 - 5" not in shown


def test_config_on_nextmove_pc_takes_stepper_and_pwm_too() -> None:
    assert "- Range: 0, 1, 2, 3, 5\n" in _hover("CONFIG.0 = 1\n", "nextmove-pc")
