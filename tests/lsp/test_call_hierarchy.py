"""Call hierarchy over GOSUBs, GOTOs and event handlers, on the manual's programs."""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import corpus, document, open_document, position, uri_of

pytestmark = pytest.mark.asyncio
# The XY table program of the guide's introduction (line 144): the main program calls #init and #main,
# and #main calls #init again; an error handler is added that calls #init too.
XY = corpus("ch01_l0144_xy_example.mnt") + "\n#ONERROR\nGOSUB init\nRETURN\n"


async def prepared(client, uri, text, needle, shift=0) -> types.CallHierarchyItem:
    [item] = await client.text_document_prepare_call_hierarchy_async(
        types.CallHierarchyPrepareParams(text_document=document(uri), position=position(text, needle, shift))
    )
    return item


async def test_who_calls_a_subroutine(client, tmp_path):
    uri = uri_of(tmp_path / "xy.mnt")
    await open_document(client, uri, XY)
    init = await prepared(client, uri, XY, "GOSUB init", 7)
    assert (init.name, init.kind, init.detail) == ("#init", types.SymbolKind.Function, "subroutine")
    assert init.selection_range.start == types.Position(line=13, character=0)
    calls = await client.call_hierarchy_incoming_calls_async(types.CallHierarchyIncomingCallsParams(item=init))
    callers = [(call.from_.name, [r.start.line for r in call.from_ranges]) for call in calls]
    assert callers == [("main program", [9]), ("#main", [35]), ("#ONERROR", [42])]
    handler = calls[2].from_
    assert (handler.kind, handler.detail) == (types.SymbolKind.Event, "event handler: the controller calls it")


async def test_where_a_part_jumps_to(client, tmp_path):
    uri = uri_of(tmp_path / "xy.mnt")
    await open_document(client, uri, XY)
    top = await prepared(client, uri, XY, "AXES")  # outside any subroutine: the main program
    assert (top.name, top.kind) == ("main program", types.SymbolKind.Module)
    calls = await client.call_hierarchy_outgoing_calls_async(types.CallHierarchyOutgoingCallsParams(item=top))
    assert [(call.to.name, [r.start.line for r in call.from_ranges]) for call in calls] == [
        ("#init", [9]),
        ("#main", [10]),
    ]
    inside = await prepared(client, uri, XY, "FOR a")  # in #main
    calls = await client.call_hierarchy_outgoing_calls_async(types.CallHierarchyOutgoingCallsParams(item=inside))
    assert [(call.to.name, [r.start.line for r in call.from_ranges]) for call in calls] == [("#init", [35])]
    assert await client.call_hierarchy_incoming_calls_async(types.CallHierarchyIncomingCallsParams(item=inside))


async def test_an_event_handler_is_called_by_the_controller_alone(client, tmp_path):
    uri = uri_of(tmp_path / "xy.mnt")
    await open_document(client, uri, XY)
    handler = await prepared(client, uri, XY, "#ONERROR", 2)
    assert handler.detail == "event handler: the controller calls it"
    assert not await client.call_hierarchy_incoming_calls_async(types.CallHierarchyIncomingCallsParams(item=handler))


async def test_a_goto_and_a_jump_in_a_macro_are_calls(client, tmp_path):
    # the guide's GOTO entry (line 11194), and a GOSUB written in a macro's text, which runs where it is used
    text = corpus("kw_GOTO_l11194.mnt") + "DEFINE again = GOSUB label1\nagain\n"
    uri = uri_of(tmp_path / "goto.mnt")
    await open_document(client, uri, text)
    label = await prepared(client, uri, text, "GOTO label1", 6)
    calls = await client.call_hierarchy_incoming_calls_async(types.CallHierarchyIncomingCallsParams(item=label))
    callers = [(call.from_.name, [(r.start.line, r.start.character) for r in call.from_ranges]) for call in calls]
    assert callers == [("main program", [(3, 5)]), ("#label1", [(7, 0)])]  # the GOTO, then the macro's use


async def test_no_item_for_a_label_that_is_never_defined(client, tmp_path):
    text = "GOSUB nowhere\nEND\n"
    uri = uri_of(tmp_path / "undefined.mnt")
    await open_document(client, uri, text)
    found = await client.text_document_prepare_call_hierarchy_async(
        types.CallHierarchyPrepareParams(text_document=document(uri), position=position(text, "nowhere"))
    )
    assert found is None
