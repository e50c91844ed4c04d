"""Hover on a keyword, and the documentation completion gives it, end with the names of its entry's See-also
list: the keywords the guide sends a reader to next (000:5669-5671)."""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import document, open_document, uri_of

pytestmark = pytest.mark.asyncio


@pytest.mark.parametrize(
    ("word", "listed"),
    [
        # 000:6731-6733, a list printed over two lines
        ("AUXENCODER", "AUXENCODERSCALE, AUXENCODERVEL, AUXENCODERWRAP, FASTAUXENCODER, MASTERSOURCE, POS"),
        # 000:8031-8032
        ("CANCEL", "ABORT, AXISERROR, CANCELALL, DEFAULT, ERR, RESET, RESETALL, STOP"),
    ],
)
async def test_hover_ends_the_entry_with_its_see_also_list(client, tmp_path, *, word, listed):
    text = f"{word}\n"
    uri = uri_of(tmp_path / "word.mnt")
    await open_document(client, uri, text)
    hover = await client.text_document_hover_async(
        types.HoverParams(text_document=document(uri), position=types.Position(line=0, character=1))
    )
    assert hover is not None and isinstance(hover.contents, types.MarkupContent)
    assert f"\n- See also: {listed}\n" in hover.contents.value


async def test_a_completion_item_documents_the_see_also_list(client, tmp_path):
    uri = uri_of(tmp_path / "typing.mnt")
    await open_document(client, uri, "CANC")
    found = await client.text_document_completion_async(
        types.CompletionParams(text_document=document(uri), position=types.Position(line=0, character=4))
    )
    items = found.items if isinstance(found, types.CompletionList) else found
    item = await client.completion_item_resolve_async(next(item for item in items if item.label == "CANCEL"))
    assert isinstance(item.documentation, types.MarkupContent)
    listed = "ABORT, AXISERROR, CANCELALL, DEFAULT, ERR, RESET, RESETALL, STOP"  # 000:8031-8032
    assert item.documentation.value.endswith(f"\n- See also: {listed}")
