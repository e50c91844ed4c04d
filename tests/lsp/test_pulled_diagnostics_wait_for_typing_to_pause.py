"""``mint.debounceMs`` is how long the server waits after the last keystroke before it checks the file again: a client
that pulls diagnostics (VS Code asks at each change) gets the check of a pause in typing, not of every keystroke."""

from __future__ import annotations

import time

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import LanguageClient, client_capabilities

from tests.lsp.conftest import EDITOR, uri_of
from tests.lsp.test_pulled_diagnostics import open_text, pull

pytestmark = pytest.mark.asyncio

DEBOUNCE_S = 0.8


@pytest_lsp.fixture(config=EDITOR)
async def pulling(lsp_client: LanguageClient):
    capabilities = client_capabilities("visual-studio-code")
    capabilities.text_document.diagnostic = types.DiagnosticClientCapabilities(related_document_support=True)
    options = {"mint": {"debounceMs": int(DEBOUNCE_S * 1000)}}
    params = types.InitializeParams(capabilities=capabilities, initialization_options=options)
    await lsp_client.initialize_session(params)
    yield
    await lsp_client.shutdown_session()


def change(client: LanguageClient, uri: str, version: int, text: str) -> None:
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(
            text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=version),
            content_changes=[types.TextDocumentContentChangeWholeDocument(text=text)],
        )
    )


async def test_a_pull_right_after_a_keystroke_is_answered_once_typing_pauses(pulling, tmp_path):
    uri = uri_of(tmp_path / "typed.mnt")
    open_text(pulling, uri, "PRINT missing\n")
    assert await pull(pulling, uri) == {"E3001"}  # a file just opened is checked at once
    change(pulling, uri, 2, "DIM missing\nPRINT missing\n")
    typed = time.perf_counter()
    assert await pull(pulling, uri) == set()
    assert time.perf_counter() - typed >= DEBOUNCE_S * 0.9


async def test_a_file_not_typed_in_is_checked_at_once(pulling, tmp_path):
    uri = uri_of(tmp_path / "opened.mnt")
    open_text(pulling, uri, "PRINT missing\n")
    opened = time.perf_counter()
    assert await pull(pulling, uri) == {"E3001"}
    assert await pull(pulling, uri) == {"E3001"}
    assert time.perf_counter() - opened < DEBOUNCE_S
