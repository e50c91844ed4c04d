"""Workspace symbols cover the programs of the workspace folder, opened or not."""

from __future__ import annotations

from pathlib import Path

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import LanguageClient, client_capabilities

from tests.lsp.conftest import EDITOR, uri_of

pytestmark = pytest.mark.asyncio
WORKSPACE = Path(__file__).parent / "workspace"


@pytest_lsp.fixture(config=EDITOR)
async def folder_client(lsp_client: LanguageClient):
    folder = types.WorkspaceFolder(uri=uri_of(WORKSPACE), name="machine")
    params = types.InitializeParams(
        capabilities=client_capabilities("visual-studio-code"), workspace_folders=[folder], root_uri=folder.uri
    )
    await lsp_client.initialize_session(params)
    yield
    await lsp_client.shutdown_session()


async def test_symbols_of_programs_never_opened_are_found(folder_client):
    found = await folder_client.workspace_symbol_async(types.WorkspaceSymbolParams(query="home"))
    names = {(symbol.name, symbol.location.uri.rsplit("/", 1)[1]) for symbol in found}
    assert names == {("#homeAxes", "station.mnt"), ("homeRate", "station.mnt")}
