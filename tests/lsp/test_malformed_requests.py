"""Every request gets an answer: malformed params, requests before ``initialize`` and after ``shutdown``.

A request pygls cannot decode used to get no answer at all, and the client
waited forever; each case here is bounded by a timeout so that a regression
fails instead of hanging.
"""

from __future__ import annotations

import asyncio
import json
import uuid
from concurrent.futures import Future
from typing import Any

import pytest
import pytest_lsp
from lsprotocol import types
from pygls.exceptions import JsonRpcException
from pytest_lsp import LanguageClient, client_capabilities

from tests.lsp.conftest import EDITOR, document, open_document, uri_of

pytestmark = pytest.mark.asyncio
HOVER = types.TEXT_DOCUMENT_HOVER
INVALID_PARAMS, INVALID_REQUEST, SERVER_NOT_INITIALIZED = -32602, -32600, -32002
MISSING = object()


@pytest_lsp.fixture(config=EDITOR)
async def fresh(lsp_client: LanguageClient):
    """A server that has not been initialized yet."""
    yield


async def raw_request(client: LanguageClient, method: str, params: Any) -> Any:
    """Send ``params`` as JSON, as they are (``MISSING``: no params at all), past the client's own typing;
    at most 10 s for the answer."""
    message: dict[str, Any] = {"jsonrpc": "2.0", "id": str(uuid.uuid4()), "method": method}
    if params is not MISSING:
        message["params"] = params
    answer: Future[Any] = Future()
    client.protocol._request_futures[message["id"]] = answer  # where the client files the answer to its id
    body = json.dumps(message).encode("utf-8")
    client.protocol.writer.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
    return await asyncio.wait_for(asyncio.wrap_future(answer), 10)


async def error_code(client: LanguageClient, method: str, params: Any) -> int:
    with pytest.raises(JsonRpcException) as raised:
        await raw_request(client, method, params)
    return raised.value.code


async def test_malformed_params_get_invalid_params(client, tmp_path):
    uri = uri_of(tmp_path / "ok.mnt")
    await open_document(client, uri, "DIM a\na = 1\n")
    here = {"uri": uri}
    for params in (
        MISSING,
        None,
        {},
        [uri, 0, 0],
        {"textDocument": here},
        {"textDocument": here, "position": {"line": -1, "character": 0}},
        {"textDocument": here, "position": {"line": 0, "character": -3}},
        {"textDocument": here, "position": {"line": "one", "character": 0}},
    ):
        assert await error_code(client, HOVER, params) == INVALID_PARAMS, params
    with pytest.raises(JsonRpcException, match="position"):
        await raw_request(client, HOVER, {"textDocument": here, "position": {"line": -1, "character": 0}})
    for method in (types.TEXT_DOCUMENT_COMPLETION, types.TEXT_DOCUMENT_DOCUMENT_SYMBOL, types.TEXT_DOCUMENT_RENAME):
        assert await error_code(client, method, [uri]) == INVALID_PARAMS, method
    answer = await client.text_document_hover_async(
        types.HoverParams(text_document=document(uri), position=types.Position(line=1, character=0))
    )
    assert answer is not None  # and the server goes on answering


async def test_a_request_before_initialize_gets_server_not_initialized(fresh, tmp_path):
    where = {"textDocument": {"uri": uri_of(tmp_path / "early.mnt")}, "position": {"line": 0, "character": 0}}
    with pytest.raises(JsonRpcException) as raised:
        await raw_request(fresh, HOVER, where)
    assert raised.value.code == SERVER_NOT_INITIALIZED
    assert "traceback" not in str(raised.value.data or "")
    fresh.text_document_did_open(  # a notification before initialize is dropped
        types.DidOpenTextDocumentParams(
            text_document=types.TextDocumentItem(
                uri=where["textDocument"]["uri"], language_id="mint", version=1, text=""
            )
        )
    )
    await fresh.initialize_session(types.InitializeParams(capabilities=client_capabilities("visual-studio-code")))
    assert await fresh.text_document_hover_async(types.HoverParams(**_typed(where))) is None
    await fresh.shutdown_session()


async def test_a_request_after_shutdown_gets_invalid_request(fresh, tmp_path):
    await fresh.initialize_session(types.InitializeParams(capabilities=client_capabilities("visual-studio-code")))
    await asyncio.wait_for(fresh.shutdown_async(None), 10)
    where = {"textDocument": {"uri": uri_of(tmp_path / "late.mnt")}, "position": {"line": 0, "character": 0}}
    assert await error_code(fresh, HOVER, where) == INVALID_REQUEST
    fresh.exit(None)


def _typed(where: dict[str, Any]) -> dict[str, Any]:
    return {
        "text_document": document(where["textDocument"]["uri"]),
        "position": types.Position(**where["position"]),
    }
