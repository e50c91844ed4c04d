"""A client that pulls diagnostics (VS Code) gets them only by pulling: pushed ones would be listed twice."""

from __future__ import annotations

import asyncio

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import LanguageClient, client_capabilities

from tests.lsp.conftest import EDITOR, document, uri_of

pytestmark = pytest.mark.asyncio


@pytest_lsp.fixture(config=EDITOR)
async def pulling(lsp_client: LanguageClient):
    capabilities = client_capabilities("visual-studio-code")
    capabilities.text_document.diagnostic = types.DiagnosticClientCapabilities(related_document_support=True)
    capabilities.workspace.diagnostics = types.DiagnosticWorkspaceClientCapabilities(refresh_support=True)
    params = types.InitializeParams(capabilities=capabilities, initialization_options={"mint": {"debounceMs": 20}})
    await lsp_client.initialize_session(params)
    yield
    await lsp_client.shutdown_session()


def open_text(client: LanguageClient, uri: str, text: str) -> None:
    client.text_document_did_open(
        types.DidOpenTextDocumentParams(
            text_document=types.TextDocumentItem(uri=uri, language_id="mint", version=1, text=text)
        )
    )


async def pull(client: LanguageClient, uri: str) -> set[str]:
    report = await client.text_document_diagnostic_async(types.DocumentDiagnosticParams(text_document=document(uri)))
    return {str(diagnostic.code) for diagnostic in report.items}


async def refreshed(client: LanguageClient, beyond: int) -> None:
    async def wait() -> None:
        while client.diagnostic_refresh_count <= beyond:
            await asyncio.sleep(0.01)

    await asyncio.wait_for(wait(), timeout=10)


async def test_nothing_is_pushed_to_a_client_that_pulls(pulling, tmp_path):
    uri = uri_of(tmp_path / "pulled.mnt")
    open_text(pulling, uri, "PRINT missing\n")
    assert await pull(pulling, uri) == {"E3001"}
    pulling.text_document_did_change(
        types.DidChangeTextDocumentParams(
            text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=2),
            content_changes=[types.TextDocumentContentChangeWholeDocument(text="DIM missing\nPRINT missing\n")],
        )
    )
    await asyncio.sleep(0.1)  # past the debounce, when a push would have gone out
    assert await pull(pulling, uri) == set()
    assert uri not in pulling.diagnostics  # the pulls were answered after any push: there was none


async def test_editing_the_configuration_asks_the_client_to_pull_the_program_again(pulling, tmp_path):
    program, config = uri_of(tmp_path / "press.mnt"), uri_of(tmp_path / "press.cfg")
    open_text(pulling, program, "PRINT stroke\n")
    open_text(pulling, config, "REM set-up\n")
    assert await pull(pulling, program) == {"E3001"}
    before = pulling.diagnostic_refresh_count
    pulling.text_document_did_change(
        types.DidChangeTextDocumentParams(
            text_document=types.VersionedTextDocumentIdentifier(uri=config, version=2),
            content_changes=[types.TextDocumentContentChangeWholeDocument(text="DIM stroke = 40\n")],
        )
    )
    await refreshed(pulling, before)
    assert await pull(pulling, program) == set()


async def test_a_new_controller_setting_asks_the_client_to_pull_again(pulling, tmp_path):
    uri = uri_of(tmp_path / "outputs.mnt")
    open_text(pulling, uri, "OUT20 = 1\n")
    assert await pull(pulling, uri) == set()  # NextMove PCI: outputs 0 to 35
    before = pulling.diagnostic_refresh_count
    pulling.workspace_did_change_configuration(
        types.DidChangeConfigurationParams(settings={"mint": {"controller": "mintdrive"}})
    )
    await refreshed(pulling, before)
    assert await pull(pulling, uri) == {"E0008"}  # MintDrive: outputs 0 to 8
