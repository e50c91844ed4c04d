"""A part of a program (the main program, a subroutine) ends at its last written line, as in the outline.

The blank lines after a subroutine's RETURN, and the REM lines that introduce the next label (which hover
shows as that label's documentation), belong to no part: expanding the selection from inside one
subroutine selects that subroutine, not the comment of the next, and the call hierarchy's item spans what
the outline's symbol spans (LSP: the item's range leaves out trailing whitespace).
"""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import document, open_document, position, uri_of
from tests.lsp.test_selection_ranges import texts

pytestmark = pytest.mark.asyncio

PROGRAM = (
    "DIM index\n"
    "GOSUB load\n"
    "GOSUB feed\n"
    "END\n"
    "\n"
    "REM Copy the recipe.\n"
    "#load\n"
    "  FOR index = 1 TO 8\n"
    "    PRINT index\n"
    "  NEXT\n"
    "RETURN\n"
    "\n"
    "REM Index the belt by one pitch.\n"
    "#feed\n"
    "  MOVER.0 = 250 : GO.0\n"
    "RETURN\n"
)
MAIN = "DIM index\nGOSUB load\nGOSUB feed\nEND\n"
LOAD = "#load\n  FOR index = 1 TO 8\n    PRINT index\n  NEXT\nRETURN\n"


def spanned(text: str, span: types.Range) -> str:
    lines = text.splitlines(keepends=True)
    start = sum(map(len, lines[: span.start.line])) + span.start.character
    return text[start : sum(map(len, lines[: span.end.line])) + span.end.character]


async def test_the_selection_grows_to_the_subroutine_and_not_the_next_ones_comment(client, tmp_path):
    uri = uri_of(tmp_path / "line.mnt")
    await open_document(client, uri, PROGRAM)
    [chain] = await client.text_document_selection_range_async(
        types.SelectionRangeParams(text_document=document(uri), positions=[position(PROGRAM, "PRINT index", 7)])
    )
    assert texts(PROGRAM, chain)[-2:] == [LOAD, PROGRAM]
    [chain] = await client.text_document_selection_range_async(
        types.SelectionRangeParams(text_document=document(uri), positions=[position(PROGRAM, "GOSUB feed", 7)])
    )
    assert texts(PROGRAM, chain)[-2:] == [MAIN, PROGRAM]


async def test_a_call_hierarchy_item_spans_its_written_lines(client, tmp_path):
    uri = uri_of(tmp_path / "line.mnt")
    await open_document(client, uri, PROGRAM)
    found = {}
    for needle in ("GOSUB load", "#load", "#feed"):
        [item] = await client.text_document_prepare_call_hierarchy_async(
            types.CallHierarchyPrepareParams(text_document=document(uri), position=position(PROGRAM, needle, 1))
        )
        found[item.name] = spanned(PROGRAM, item.range)
    assert found == {"main program": MAIN, "#load": LOAD, "#feed": "#feed\n  MOVER.0 = 250 : GO.0\nRETURN\n"}


async def test_a_jump_is_still_the_call_of_the_part_it_stands_in(client, tmp_path):
    uri = uri_of(tmp_path / "line.mnt")
    await open_document(client, uri, PROGRAM)
    [feed] = await client.text_document_prepare_call_hierarchy_async(
        types.CallHierarchyPrepareParams(text_document=document(uri), position=position(PROGRAM, "#feed", 1))
    )
    calls = await client.call_hierarchy_incoming_calls_async(types.CallHierarchyIncomingCallsParams(item=feed))
    assert [(call.from_.name, [r.start.line for r in call.from_ranges]) for call in calls] == [("main program", [2])]
