"""Hover on a predefined constant, and the detail completion gives it, say where the keyword it is a value of
refuses it on the editor's controller: CONFIG's motor types are ticked per controller (000:8431-8443), so
``_cfSTEPPER`` configures no axis of a NextMove BX, as ``mint check`` holds ``CONFIG.0 = _cfSTEPPER`` there."""

from __future__ import annotations

import pytest
from lsprotocol import types

from mintlang.lsp.features.hover import hover_text
from mintlang.lsp.workspace import Analyses, Settings
from tests.lsp.conftest import document, open_document, uri_of


def _hover(text: str, controller: str) -> str:
    analyses = Analyses(read=lambda _: None, settings=Settings.from_options({"controller": controller}))
    shown = hover_text(analyses.snapshot("file:///constant.mnt", text, 1), text.index("_") + 1)
    assert shown is not None
    return shown[0]


@pytest.mark.parametrize(
    ("text", "controller", "refused"),
    [
        # 000:8439: stepper ticked for NextMove PCI and PC, not BX, ServoNode 51 or MintDrive
        ("CONFIG.0 = _cfSTEPPER\n", "nextmove-bx", "Not a value CONFIG accepts on NextMove BX (0, 1, 5)"),
        ("CONFIG.0 = _cfSTEPPER\n", "servonode51", "Not a value CONFIG accepts on ServoNode 51 (1)"),
        # 000:13926-13929: MASTERSOURCE on MintDrive and ServoNode 51 is 2 or 3, not _msPOS (0)
        ("MASTERSOURCE.0 = _msPOS\n", "mintdrive", "Not a value MASTERSOURCE accepts on MintDrive (2, 3)"),
    ],
)
def test_hover_says_the_controller_refuses_it(text: str, controller: str, refused: str) -> None:
    assert refused in _hover(text, controller)


@pytest.mark.parametrize(
    ("text", "controller"),
    [
        ("CONFIG.0 = _cfSTEPPER\n", "nextmove-pci"),  # 000:8439: ticked for NextMove PCI
        ("MASTERSOURCE.0 = _msPOS\n", "nextmove-bx"),  # 000:13925: 0 ≤ x ≤ 4 on NextMove
    ],
)
def test_hover_says_nothing_where_the_controller_takes_it(text: str, controller: str) -> None:
    assert "Not a value" not in _hover(text, controller)


@pytest.mark.asyncio
async def test_completion_details_it_where_the_controller_refuses_it(client, tmp_path):
    (tmp_path / "mint.toml").write_text('controller = "nextmove-bx"\n', encoding="utf-8")
    uri = uri_of(tmp_path / "axes.mnt")
    text = "CONFIG.0 = _cf"
    await open_document(client, uri, text)
    found = await client.text_document_completion_async(
        types.CompletionParams(text_document=document(uri), position=types.Position(line=0, character=len(text)))
    )
    items = {item.label: item for item in (found.items if isinstance(found, types.CompletionList) else found)}
    assert items["_cfSTEPPER"].detail.endswith("; not a value CONFIG accepts on NextMove BX (0, 1, 5)")
    assert "not a value" not in items["_cfSERVO"].detail
