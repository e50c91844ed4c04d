"""The call hierarchy names a label as the outline does (test_outline_tells_subroutines_from_labels): one only a
GOTO names is a place in the code, a plain label (000:11187-11188), not a subroutine, which a GOSUB calls
(000:1841-1850). Its GOTOs are still its calls."""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import document, open_document, position, uri_of

pytestmark = pytest.mark.asyncio

TEXT = "DIM n\nGOSUB init\n#more\n  n = n + 1\n  IF n < 10 THEN GOTO more\nEND\n#init\n  n = 0\nRETURN\n"


async def _prepared(client, uri, needle: str) -> types.CallHierarchyItem:
    [item] = await client.text_document_prepare_call_hierarchy_async(
        types.CallHierarchyPrepareParams(text_document=document(uri), position=position(TEXT, needle, 1))
    )
    return item


async def test_a_goto_target_is_a_label_and_a_gosub_target_a_subroutine(client, tmp_path):
    uri = uri_of(tmp_path / "labels.mnt")
    await open_document(client, uri, TEXT)
    more = await _prepared(client, uri, "#more")
    assert (more.name, more.kind, more.detail) == ("#more", types.SymbolKind.Key, "label")
    calls = await client.call_hierarchy_incoming_calls_async(types.CallHierarchyIncomingCallsParams(item=more))
    assert [(call.from_.name, [r.start.line for r in call.from_ranges]) for call in calls] == [("#more", [4])]
    init = await _prepared(client, uri, "#init")
    assert (init.name, init.kind, init.detail) == ("#init", types.SymbolKind.Function, "subroutine")
