"""In a MintMT program the hover and a completion item's description write a keyword's formats as MintMT does,
its axes or channel in round brackets (MT-18: ``MOVER(0)``, ``IDLE(0)``), as signature help does: a MintMT
programmer is shown the brackets the notes write (004:98-133), not v4's ``[axes]`` and ``.axis``."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from tests.lsp import test_mintmt
from tests.lsp.conftest import document, open_document, position

pytestmark = pytest.mark.asyncio
client = test_mintmt.client  # the server reading each file's dialect from its text (mint.dialect = auto)

PROGRAM = "Loop\n  If IDLE(0) Then\n    MOVER(0) = 10\n  End If\nEnd Loop\n"


async def _hover(client: LanguageClient, uri: str, needle: str) -> str:
    found = await client.text_document_hover_async(
        types.HoverParams(text_document=document(uri), position=position(PROGRAM, needle, 1))
    )
    assert isinstance(found, types.Hover) and isinstance(found.contents, types.MarkupContent), needle
    return found.contents.value


async def test_the_hover_writes_the_axes_in_round_brackets(client: LanguageClient) -> None:
    uri = "file:///work/formats.mnt"
    await open_document(client, uri, PROGRAM)
    idle = await _hover(client, uri, "IDLE")
    assert "v = IDLE(axis)" in idle and "IDLE[" not in idle  # v4 writes v = IDLE[axis] (000:11726-11727)
    mover = await _hover(client, uri, "MOVER")
    assert "MOVER(axes) = <expression>" in mover and "MOVER[" not in mover


async def test_a_completion_items_description_writes_them_so_too(client: LanguageClient) -> None:
    uri = "file:///work/formats_completion.mnt"
    text = "Loop\n  MOVE\nEnd Loop\n"
    await open_document(client, uri, text)
    found = await client.text_document_completion_async(
        types.CompletionParams(text_document=document(uri), position=position(text, "MOVE\n", 4))
    )
    items = found.items if isinstance(found, types.CompletionList) else found or []
    mover = next(item for item in items if item.label == "MOVER")
    described = await client.completion_item_resolve_async(mover)
    assert "MOVER(axes) = <expression>" in described.documentation.value
