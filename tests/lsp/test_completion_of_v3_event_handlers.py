"""After ``#`` in a Mint v3 program the handlers offered are the v3 guide's: #ONERROR, #STOP, the digital inputs'
#IN0 .. #IN7 and the position latch's #FASTPOS (001:414-417, 2523-2525). v4's #COMMS1 .. #COMMS5 and #FASTINx are
no v3 events: a v3 program naming one has a plain label the controller never calls."""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import open_document, uri_of
from tests.lsp.test_completion import labels_at

pytestmark = pytest.mark.asyncio
V3_HANDLERS = {"#ONERROR", "#STOP", "#FASTPOS", *(f"#IN{number}" for number in range(8))}


async def test_a_v3_program_is_offered_the_v3_handlers(client, tmp_path):
    client.workspace_did_change_configuration(types.DidChangeConfigurationParams(settings={"mint": {"dialect": "v3"}}))
    text = "box = 1\n#\n"
    uri = uri_of(tmp_path / "old_events.mnt")
    await open_document(client, uri, text)
    assert set(await labels_at(client, uri, text, "#", 1)) == V3_HANDLERS
