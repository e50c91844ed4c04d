"""Document highlight tells a write in a macro's text from a read, as it does in the program's lines.

A macro's text runs where the macro is used (000:1452-1459): ``DEFINE bump = count = count + 1`` assigns
``count`` each time ``bump`` runs. Its first ``count`` is written and its second read, as they would be in
a line of the program; the highlight marked both read.
"""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import document, open_document, position, uri_of

pytestmark = pytest.mark.asyncio
WRITE, READ = types.DocumentHighlightKind.Write, types.DocumentHighlightKind.Read


async def highlights(client, tmp_path, text: str, needle: str) -> list[tuple[int, int, types.DocumentHighlightKind]]:
    uri = uri_of(tmp_path / "macro.mnt")
    await open_document(client, uri, text)
    found = await client.text_document_document_highlight_async(
        types.DocumentHighlightParams(text_document=document(uri), position=position(text, needle))
    )
    return sorted((h.range.start.line, h.range.start.character, h.kind) for h in found)


async def test_an_assignment_in_a_macros_text_is_a_write(client, tmp_path):
    text = "DIM count = 0\nDEFINE bump = count = count + 1\nbump\nPRINT count\n"
    assert await highlights(client, tmp_path, text, "count") == [
        (0, 4, WRITE),
        (1, 14, WRITE),
        (1, 22, READ),
        (3, 6, READ),
    ]


async def test_a_for_counter_and_an_element_in_a_macros_text_are_writes(client, tmp_path):
    text = "DIM i\nDIM table(4)\nDEFINE fill = FOR i = 1 TO 4 : table(i) = i : NEXT\nfill\n"
    counter = [(0, 4, WRITE), (2, 18, WRITE), (2, 37, READ), (2, 42, READ)]
    assert await highlights(client, tmp_path, text, "i\n") == counter
    assert await highlights(client, tmp_path, text, "table") == [(1, 4, WRITE), (2, 31, WRITE)]
