"""Hover shows the attributes row the guide prints for the editor's controller, says whose row it shows
where the guide prints none for that controller, and says when the guide lists no controllers at all."""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import document, open_document, uri_of

pytestmark = pytest.mark.asyncio
NEXTMOVES = "NextMove PCI, NextMove PC, NextMove BX"


@pytest.mark.parametrize(
    ("word", "controller", "shown", "not_shown"),
    [
        # 000:11549-11555: HOMEINPUT's rows are NM PC (0, 0 ≤ x ≤ 23), NM BX (0, 0 ≤ x ≤ 15), MintDrive
        pytest.param(
            "HOMEINPUT",
            "nextmove-pci",
            "- Attributes: the guide's row for NextMove PC (it prints none for NextMove PCI)\n",
            "Not available",
            id="homeinput-no-row-on-nextmove-pci",
        ),
        pytest.param(
            "HOMEINPUT", "nextmove-bx", "- Default: 0\n- Range: 0 ≤ x ≤ 15\n", "Attributes:", id="homeinput-bx"
        ),
        pytest.param(
            "HOMEINPUT", "mintdrive", "- Default: -1\n- Range: -1 ≤ x ≤ 17\n", "Attributes:", id="homeinput-mintdrive"
        ),
        # 000:15783-15784: SCALE's NextMove row (1.0, 0 ≤ x ≤ 8388607.0) and MintDrive's (1, 1 ≤ x ≤ 65535)
        pytest.param(
            "SCALE", "nextmove-pc", "- Default: 1.0\n- Range: 0 ≤ x ≤ 8388607.0\n", "Attributes:", id="scale-pc"
        ),
        pytest.param("SCALE", "mintdrive", "- Default: 1\n- Range: 1 ≤ x ≤ 65535\n", "Attributes:", id="scale-md"),
        # 000:8720-8737: DAC lists MintDrive among its controllers, its one row is NextMove's
        pytest.param(
            "DAC",
            "mintdrive",
            f"- Attributes: the guide's row for {NEXTMOVES} (it prints none for MintDrive)\n",
            "Not available",
            id="dac-no-row-on-mintdrive",
        ),
        # 000:8797-8815: DACLIMITMAX is the NextMoves' only
        pytest.param(
            "DACLIMITMAX",
            "mintdrive",
            f"- Controllers: {NEXTMOVES}\n- **Not available on MintDrive**",
            "\n- Controllers: \n",
            id="daclimitmax-not-on-mintdrive",
        ),
        # 000:14634 and 17704: MOVESTATUS is an advanced stub whose quick-reference row ticks no controller
        pytest.param(
            "MOVESTATUS",
            "nextmove-pci",
            "- Controllers: not listed in the guide",
            "Not available",
            id="movestatus-controllers-not-listed",
        ),
    ],
)
async def test_the_attributes_shown_are_the_controllers(client, tmp_path, *, word, controller, shown, not_shown):
    client.workspace_did_change_configuration(
        types.DidChangeConfigurationParams(settings={"mint": {"controller": controller}})
    )
    text = f"{word}\n"
    uri = uri_of(tmp_path / "word.mnt")
    await open_document(client, uri, text)
    hover = await client.text_document_hover_async(
        types.HoverParams(text_document=document(uri), position=types.Position(line=0, character=1))
    )
    assert hover is not None and isinstance(hover.contents, types.MarkupContent)
    assert shown in hover.contents.value
    assert not_shown not in hover.contents.value
