"""A MintMT ``Event`` block may name v4's events as well as the notes' ones (MT-13: ONERROR, TIMER, STOP, INx,
FASTINx, CANx), and the controller runs it for them: the editor describes those names and offers them after
``Event`` as it does ``Comms1`` and ``MOVEBUFFERLOW``."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from tests.lsp import test_mintmt
from tests.lsp.conftest import document, open_document, position

pytestmark = pytest.mark.asyncio
client = test_mintmt.client  # the server reading each file's dialect from its text (mint.dialect = auto)


@pytest.mark.parametrize(
    ("name", "said"),
    [
        ("TIMER", "TIMEREVENT"),  # the periodic timer whose interval TIMEREVENT sets (000:4992-4994)
        ("ONERROR", "error"),  # the error handler (000:1889, 4556-4558)
        ("STOP", "stop input"),  # an axis's stop input becoming active (000:4934-4936)
        ("IN3", "digital input 3"),  # a user digital input's handler (000:1896)
        ("FASTIN1", "fast position latch input 1"),  # 000:1894
        ("CAN2", "CAN channel 2"),  # 000:1891
    ],
)
async def test_the_name_of_an_event_block_for_a_v4_event_is_described(
    client: LanguageClient, name: str, said: str
) -> None:
    uri = f"file:///work/event_{name}.mnt"
    text = f"Loop\nEnd Loop\nEvent {name}\n  Print 1\nEnd Event\n"
    await open_document(client, uri, text)
    found = await client.text_document_hover_async(
        types.HoverParams(text_document=document(uri), position=position(text, f"Event {name}", 7))
    )
    assert isinstance(found, types.Hover) and isinstance(found.contents, types.MarkupContent)
    assert found.contents.value.startswith(f"**{name}** — MintMT event")
    assert said in found.contents.value
    word = await client.text_document_hover_async(
        types.HoverParams(text_document=document(uri), position=position(text, "Event"))
    )
    assert isinstance(word, types.Hover) and isinstance(word.contents, types.MarkupContent)
    assert name.rstrip("0123456789") in word.contents.value  # the Event block's hover names the event too


async def test_after_event_the_v4_events_are_offered_too(client: LanguageClient) -> None:
    uri = "file:///work/event_offered.mnt"
    text = "Loop\nEnd Loop\nEvent \n"
    await open_document(client, uri, text)
    found = await client.text_document_completion_async(
        types.CompletionParams(text_document=document(uri), position=position(text, "Event \n", 6))
    )
    items = found.items if isinstance(found, types.CompletionList) else found or []
    labels = [item.label for item in items]
    assert {"Comms1", "MOVEBUFFERLOW", "ONERROR", "TIMER", "STOP", "IN0", "FASTIN0", "CAN1"} <= set(labels)
    assert "COMMS1" not in labels  # the notes spell it Comms1 (002:82), offered once
    assert all(item.documentation is not None for item in items)


async def test_after_event_an_event_already_handled_is_not_offered(client: LanguageClient) -> None:
    # a second block for an event already handled, by an Event block or by v4's label, is error 2003 (MT-13),
    # as a second handler label is after '#' (E3004)
    uri = "file:///work/event_handled.mnt"
    text = "Loop\nEnd Loop\nEvent Comms1\nEnd Event\n#TIMER\nReturn\nEvent \n"
    await open_document(client, uri, text)
    found = await client.text_document_completion_async(
        types.CompletionParams(text_document=document(uri), position=position(text, "Event \n", 6))
    )
    labels = {item.label for item in (found.items if isinstance(found, types.CompletionList) else found or [])}
    assert {"Comms2", "MOVEBUFFERLOW", "ONERROR"} <= labels
    assert not {"Comms1", "TIMER"} & labels


async def test_after_hash_an_event_an_event_block_handles_is_not_offered(client: LanguageClient) -> None:
    # MT-13: a v4 label for an event an Event block handles (#COMMS1 beside Event Comms1) is error 2003
    uri = "file:///work/hash_handled.mnt"
    text = "Loop\nEnd Loop\nEvent Comms1\nEnd Event\n#\n"
    await open_document(client, uri, text)
    found = await client.text_document_completion_async(
        types.CompletionParams(text_document=document(uri), position=position(text, "#\n", 1))
    )
    labels = {item.label for item in (found.items if isinstance(found, types.CompletionList) else found or [])}
    assert {"#COMMS2", "#TIMER"} <= labels
    assert "#COMMS1" not in labels
