"""Hover on an event handler's label says so only where the editor's controller calls it: a ``#INx`` past the
controller's digital inputs, or a ``#FASTINx`` for a fast input it lacks, is a subroutine nothing calls, as
``mint check`` warns (W109), not a handler of that controller's."""

from __future__ import annotations

import pytest

from mintlang.lsp.features.hover import hover_text
from mintlang.lsp.workspace import Analyses, Settings

PROGRAM = "END\n#IN3\nRETURN\n#IN7\nRETURN\n#FASTIN1\nRETURN\n"


def _hover(label: str, controller: str) -> str:
    analyses = Analyses(read=lambda _: None, settings=Settings.from_options({"controller": controller}))
    shown = hover_text(analyses.snapshot("file:///events.mnt", PROGRAM, 1), PROGRAM.index(label) + 1)
    assert shown is not None
    return shown[0]


@pytest.mark.parametrize(
    ("label", "controller", "kind"),
    [
        # 000:5951: ServoNode 51 has 6 digital inputs, #IN0 .. #IN5
        ("#IN3", "servonode51", "event handler (IN)"),
        # 000:5949: NextMove BX has 16, #IN0 .. #IN15
        ("#IN7", "nextmove-bx", "event handler (IN)"),
        # 000:5886: NextMove BX's dedicated fast input 1 calls #FASTIN1
        ("#FASTIN1", "nextmove-bx", "event handler (FASTIN)"),
    ],
)
def test_a_handler_the_controller_calls(label: str, controller: str, kind: str) -> None:
    assert _hover(label, controller).startswith(f"**{label}** — {kind}, at line ")


@pytest.mark.parametrize(
    ("label", "controller", "why"),
    [
        ("#IN7", "servonode51", "ServoNode 51 has digital inputs 0 to 5"),  # 000:5951
        ("#FASTIN1", "mintdrive", "MintDrive calls #FASTINx for x = 0, 2 only"),  # 000:5881-5888
    ],
)
def test_a_handler_the_controller_never_calls_is_a_label(label: str, controller: str, why: str) -> None:
    shown = _hover(label, controller)
    assert shown.startswith(f"**{label}** — label, at line ")
    assert "event handler" not in shown.split("\n")[0]
    assert why in shown
