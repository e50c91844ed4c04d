"""A handler that raises is answered with an error response (requests) or logged (notifications);
the server goes on answering."""

from __future__ import annotations

import sys

import pytest
import pytest_lsp
from lsprotocol import types
from pygls.exceptions import JsonRpcException
from pytest_lsp import ClientServerConfig, LanguageClient, client_capabilities

from tests.lsp.conftest import change, document, editor_client, open_document, published, uri_of
from tests.lsp.faulty_server import INJECTED_FAILURE

pytestmark = pytest.mark.asyncio
ORIGIN = types.Position(line=0, character=0)


@pytest_lsp.fixture(
    config=ClientServerConfig(
        server_command=[sys.executable, "-m", "tests.lsp.faulty_server"], client_factory=editor_client
    )
)
async def faulty(lsp_client: LanguageClient):
    params = types.InitializeParams(
        capabilities=client_capabilities("visual-studio-code"), initialization_options={"mint": {"debounceMs": 0}}
    )
    await lsp_client.initialize_session(params)
    yield
    await lsp_client.shutdown_session()


async def test_a_failing_request_gets_an_error_response(faulty, tmp_path):
    uri = uri_of(tmp_path / "ok.mnt")
    await open_document(faulty, uri, "DIM a\na = 1\n")
    with pytest.raises(JsonRpcException, match="injected hover failure"):
        await faulty.text_document_hover_async(types.HoverParams(text_document=document(uri), position=ORIGIN))
    symbols = await faulty.text_document_document_symbol_async(types.DocumentSymbolParams(text_document=document(uri)))
    assert [symbol.name for symbol in symbols] == ["a"]


async def test_a_failing_notification_leaves_the_server_answering(faulty, tmp_path):
    uri = uri_of(tmp_path / "broken.mnt")
    faulty.text_document_did_open(
        types.DidOpenTextDocumentParams(
            text_document=types.TextDocumentItem(uri=uri, language_id="mint", version=1, text=INJECTED_FAILURE + "\n")
        )
    )
    change(faulty, uri, 2, ((0, 0), (0, len(INJECTED_FAILURE))), "DIM b : PRINT b")
    assert await published(faulty, uri) == []
    symbols = await faulty.text_document_document_symbol_async(types.DocumentSymbolParams(text_document=document(uri)))
    assert [symbol.name for symbol in symbols] == ["b"]
