"""Linked editing of a label with its GOSUBs and GOTOs."""

from __future__ import annotations

import re

import pytest
from lsprotocol import types

from mintlang.lsp.features.linked_editing import WORD
from tests.lsp.conftest import corpus, document, open_document, position, uri_of

pytestmark = pytest.mark.asyncio
XY = corpus("ch01_l0144_xy_example.mnt")  # the guide's XY table program (line 144): GOSUB init twice


async def ranges_at(client, uri, text, needle, shift=0) -> types.LinkedEditingRanges | None:
    return await client.text_document_linked_editing_range_async(
        types.LinkedEditingRangeParams(text_document=document(uri), position=position(text, needle, shift))
    )


async def test_a_label_and_its_gosubs_edit_together(client, tmp_path):
    uri = uri_of(tmp_path / "xy.mnt")
    await open_document(client, uri, XY)
    for needle, shift in (("#init", 2), ("GOSUB init", 7)):
        found = await ranges_at(client, uri, XY, needle, shift)
        places = [(r.start.line, r.start.character, r.end.character) for r in found.ranges]
        assert places == [(13, 1, 5), (9, 6, 10), (35, 6, 10)]  # the name only, never the #
    assert re.fullmatch(WORD, "init_2") and not re.fullmatch(WORD, "2init")


async def test_a_jump_in_a_macro_and_a_goto_are_linked_too(client, tmp_path):
    text = "DEFINE again = GOTO label1\nGOTO label1\nagain\n#label1\nEND\n"
    uri = uri_of(tmp_path / "goto.mnt")
    await open_document(client, uri, text)
    found = await ranges_at(client, uri, text, "#label1", 3)
    assert {(r.start.line, r.start.character) for r in found.ranges} == {(0, 20), (1, 5), (3, 1)}


@pytest.mark.parametrize(
    ("text", "needle", "why"),
    [
        ("GOSUB init\nGOSUB INIT\nEND\n#init\nRETURN\n", "#init", "two spellings: rename writes one"),
        ("DIM a\na = 1\n", "a = 1", "a variable"),
        ("END\n#ONERROR\nRETURN\n", "#ONERROR", "an event handler keeps its name"),
        ("GOSUB nowhere\nEND\n", "nowhere", "a label never defined"),
    ],
)
async def test_no_linked_ranges(client, tmp_path, text, needle, why):
    uri = uri_of(tmp_path / "none.mnt")
    await open_document(client, uri, text)
    assert await ranges_at(client, uri, text, needle, 2) is None, why
