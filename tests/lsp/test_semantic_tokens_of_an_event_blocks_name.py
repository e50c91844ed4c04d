"""The word after MintMT's ``Event`` names the event the block handles (MT-13; 002:82-84, 004:114): it is
coloured as the label of a v4 handler is (``#COMMS1``, a function), not as a variable the program has none of."""

from __future__ import annotations

import pytest

from tests.lsp import test_mintmt
from tests.lsp.conftest import open_document
from tests.lsp.test_structure import coloured

pytestmark = pytest.mark.asyncio
client = test_mintmt.client  # the server reading each file's dialect from its text (mint.dialect = auto)


async def test_an_event_blocks_name_is_coloured_as_a_handlers_label(client):
    text = (
        "Loop\nEnd Loop\nEvent Comms1\n  Print 1\nEnd Event\nEvent TIMER\nEnd Event\nEvent MOVEBUFFERLOW\nEnd Event\n"
    )
    uri = "file:///work/event_colours.mnt"
    await open_document(client, uri, text)
    decoded = [(word, kind) for _, word, kind, _ in await coloured(client, uri, text)]
    for name in ("Comms1", "TIMER", "MOVEBUFFERLOW"):
        assert (name, "function") in decoded, name
    assert ("Event", "keyword") in decoded
