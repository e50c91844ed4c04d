"""Offsets ↔ LSP positions with characters outside ASCII and the Basic Multilingual Plane."""

from __future__ import annotations

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import LanguageClient, client_capabilities

from mintlang.lsp.positions import Positions
from tests.lsp.conftest import EDITOR, document, open_document, uri_of

TEXT = 'REM 😀 é\r\nPRINT "😀" : DIM a\nlast'


@pytest.mark.parametrize(
    ("encoding", "column_of_dim"),
    [
        (types.PositionEncodingKind.Utf16, 13),
        (types.PositionEncodingKind.Utf8, 15),
        (types.PositionEncodingKind.Utf32, 12),
    ],
)
def test_round_trip(encoding, column_of_dim):
    positions = Positions(TEXT, encoding)
    offset = TEXT.index("DIM")
    assert positions.position(offset) == types.Position(line=1, character=column_of_dim)
    assert positions.offset(types.Position(line=1, character=column_of_dim)) == offset
    assert positions.offset(types.Position(line=0, character=99)) == TEXT.index("\r")
    assert positions.offset(types.Position(line=9, character=0)) == len(TEXT)
    assert positions.line_count == 3


@pytest.mark.asyncio
async def test_hover_after_an_astral_character(client, tmp_path):
    uri = uri_of(tmp_path / "emoji.mnt")
    text = 'DIM b\nPRINT "😀" : b = 1\n'
    await open_document(client, uri, text)
    hover = await client.text_document_hover_async(
        types.HoverParams(text_document=document(uri), position=types.Position(line=1, character=13))
    )
    assert hover.contents.value.startswith("**b** — variable")
    assert hover.range.start == types.Position(line=1, character=13)


@pytest_lsp.fixture(config=EDITOR)
async def utf8_client(lsp_client: LanguageClient):
    capabilities = client_capabilities("visual-studio-code")
    capabilities.general = types.GeneralClientCapabilities(position_encodings=[types.PositionEncodingKind.Utf8])
    await lsp_client.initialize_session(types.InitializeParams(capabilities=capabilities))
    yield
    await lsp_client.shutdown_session()


@pytest.mark.asyncio
async def test_utf8_when_the_client_prefers_it(utf8_client, tmp_path):
    uri = uri_of(tmp_path / "emoji8.mnt")
    text = 'DIM b\nPRINT "😀é" : b = 1\n'
    [diagnostic] = await open_document(utf8_client, uri, text + "c = 2\n")
    assert diagnostic.code == "E3001"
    hover = await utf8_client.text_document_hover_async(
        types.HoverParams(text_document=document(uri), position=types.Position(line=1, character=17))
    )
    assert hover.range.start == types.Position(line=1, character=17)  # 😀 is four bytes, é two
