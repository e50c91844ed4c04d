"""The name after MintMT's ``Event`` is the event the block handles (MT-13): rename refuses it as it refuses a v4
handler's label (``#ONERROR``), saying why, rather than as no name at all: the controller calls the block by it."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pygls.exceptions import JsonRpcException

from tests.lsp import test_mintmt
from tests.lsp.conftest import document, open_document, position

pytestmark = pytest.mark.asyncio
client = test_mintmt.client  # the server reading each file's dialect from its text (mint.dialect = auto)


async def test_an_event_blocks_name_keeps_its_name(client):
    text = "Dim a\nLoop\nEnd Loop\nEvent Comms1\n  a = 1\nEnd Event\n"
    uri = "file:///work/event_rename.mnt"
    await open_document(client, uri, text)
    with pytest.raises(JsonRpcException, match="Comms1 is the event this block handles"):
        await client.text_document_prepare_rename_async(
            types.PrepareRenameParams(text_document=document(uri), position=position(text, "Comms1", 2))
        )
