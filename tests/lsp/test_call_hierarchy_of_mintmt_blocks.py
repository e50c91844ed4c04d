"""In MintMT an Event block is a part of its own in the call hierarchy, as a v4 handler's section is: the program
never runs into it from the line above (MT-7), the controller runs it when its event happens (002:82-84), so a
GOSUB in it is a call from ``Event Comms1``, not from the main program around it."""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp import test_mintmt
from tests.lsp.conftest import open_document
from tests.lsp.test_call_hierarchy import prepared

pytestmark = pytest.mark.asyncio
client = test_mintmt.client  # the server reading each file's dialect from its text (mint.dialect = auto)

PROGRAM = (
    "Dim a\n"
    "Loop\n"
    "  GoSub work\n"  # line 2: the main program's call
    "End Loop\n"
    "Event Comms1\n"
    "  GoSub work\n"  # line 5: the event block's
    "End Event\n"
    "#work\n"
    "  a = 0\n"
    "Return\n"
)


async def test_a_gosub_in_an_event_block_is_a_call_from_the_block(client):
    uri = "file:///work/event_calls.mnt"
    await open_document(client, uri, PROGRAM)
    work = await prepared(client, uri, PROGRAM, "#work", 1)
    calls = await client.call_hierarchy_incoming_calls_async(types.CallHierarchyIncomingCallsParams(item=work))
    callers = [(call.from_.name, call.from_.kind, [r.start.line for r in call.from_ranges]) for call in calls]
    assert callers == [("main program", types.SymbolKind.Module, [2]), ("Event Comms1", types.SymbolKind.Event, [5])]


async def test_the_main_program_and_the_block_each_jump_from_their_own_lines(client):
    uri = "file:///work/event_parts.mnt"
    await open_document(client, uri, PROGRAM)
    top = await prepared(client, uri, PROGRAM, "Loop")
    calls = await client.call_hierarchy_outgoing_calls_async(types.CallHierarchyOutgoingCallsParams(item=top))
    assert [(call.to.name, [r.start.line for r in call.from_ranges]) for call in calls] == [("#work", [2])]
    block = await prepared(client, uri, PROGRAM, "  GoSub work\nEnd Event", 2)  # in the Event block
    assert (block.name, block.detail) == ("Event Comms1", "event handler: the controller calls it")
    calls = await client.call_hierarchy_outgoing_calls_async(types.CallHierarchyOutgoingCallsParams(item=block))
    assert [(call.to.name, [r.start.line for r in call.from_ranges]) for call in calls] == [("#work", [5])]
    assert not await client.call_hierarchy_incoming_calls_async(types.CallHierarchyIncomingCallsParams(item=block))
