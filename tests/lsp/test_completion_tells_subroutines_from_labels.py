"""Completion names a label as the outline does (test_outline_tells_subroutines_from_labels): a label a GOSUB
names is a subroutine (000:1841-1850), offered as a function; one only a GOTO names is a place in the code
(000:11187-11188), offered as a reference, not a function. After ``#`` a label jumped to and not yet written is
named by the jumps that name it. Every label was offered as a function."""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import document, open_document, position, uri_of

pytestmark = pytest.mark.asyncio

SUBROUTINE, LABEL = types.CompletionItemKind.Function, types.CompletionItemKind.Reference

TEXT = "DIM n\nGOSUB init\n#more\n  n = n + 1\n  IF n < 10 THEN GOTO more\nEND\n#init\n  n = 0\nRETURN\nGOTO \n"


async def _items(client, uri, text: str, needle: str, shift: int) -> dict[str, tuple[object, object]]:
    found = await client.text_document_completion_async(
        types.CompletionParams(text_document=document(uri), position=position(text, needle, shift))
    )
    return {item.label: (item.kind, item.detail) for item in found.items}


async def test_a_goto_target_is_offered_as_a_label_and_a_gosub_target_as_a_subroutine(client, tmp_path):
    uri = uri_of(tmp_path / "labels.mnt")
    await open_document(client, uri, TEXT)
    assert await _items(client, uri, TEXT, "GOTO \n", 5) == {
        "more": (LABEL, "label"),
        "init": (SUBROUTINE, "subroutine"),
    }


async def test_a_label_to_write_is_named_by_the_jumps_that_name_it(client, tmp_path):
    text = "DIM n\nGOSUB setup\nIF n THEN GOTO retry\nEND\n#\n"
    uri = uri_of(tmp_path / "to_write.mnt")
    await open_document(client, uri, text)
    items = await _items(client, uri, text, "#\n", 1)
    assert (items["#setup"][0], items["#retry"][0]) == (SUBROUTINE, LABEL)
