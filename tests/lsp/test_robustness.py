"""Never opened, binary and huge documents, and a broken line: answered, never fatal."""

from __future__ import annotations

import pytest
from lsprotocol import types

from mintlang.lsp.workspace import MAX_CHARACTERS
from tests.lsp.conftest import document, open_document, uri_of

pytestmark = pytest.mark.asyncio
ORIGIN = types.Position(line=0, character=0)


async def test_requests_for_documents_never_opened(client, tmp_path):
    uri = uri_of(tmp_path / "ghost.mnt")
    here = document(uri)
    assert await client.text_document_hover_async(types.HoverParams(text_document=here, position=ORIGIN)) is None
    completion = await client.text_document_completion_async(
        types.CompletionParams(text_document=here, position=ORIGIN)
    )
    assert not completion.items
    assert not await client.text_document_folding_range_async(types.FoldingRangeParams(text_document=here))
    assert not await client.text_document_document_symbol_async(types.DocumentSymbolParams(text_document=here))
    options = types.FormattingOptions(tab_size=2, insert_spaces=True)
    formatting = types.DocumentFormattingParams(text_document=here, options=options)
    assert not await client.text_document_formatting_async(formatting)
    report = await client.text_document_diagnostic_async(types.DocumentDiagnosticParams(text_document=here))
    assert not report.items


async def test_binary_file(client, tmp_path):
    uri = uri_of(tmp_path / "image.mnt")
    diagnostics = await open_document(client, uri, "\x00\x01\x02PK\x03\x04" * 100)
    assert [d.message for d in diagnostics] == ["binary file: not analysed"]
    hover = await client.text_document_hover_async(types.HoverParams(text_document=document(uri), position=ORIGIN))
    assert hover is None


async def test_huge_file_is_not_analysed(client, tmp_path):
    uri = uri_of(tmp_path / "huge.mnt")
    diagnostics = await open_document(client, uri, "REM padding\n" * (MAX_CHARACTERS // 10))
    assert "not analysed" in diagnostics[0].message


async def test_garbage_and_positions_past_the_end(client, tmp_path):
    uri = uri_of(tmp_path / "garbage.mnt")
    text = 'IF ((( DO\n£$%^ "unterminated\nFOR = TO\n#\n'
    diagnostics = await open_document(client, uri, text)
    assert diagnostics
    far = types.Position(line=999, character=999)
    assert await client.text_document_hover_async(types.HoverParams(text_document=document(uri), position=far)) is None
    completion = await client.text_document_completion_async(
        types.CompletionParams(text_document=document(uri), position=far)
    )
    assert completion is not None
