"""A configuration file changed on disk re-checks the open programs paired with it.

A client that watches files is asked to (dynamic registration) and tells the
server what changed; for one that cannot, the server looks at the partner
files itself, once a second.
"""

from __future__ import annotations

import asyncio
from pathlib import Path

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import LanguageClient, client_capabilities

from mintlang.lsp.features.watched_files import globs
from tests.lsp.conftest import EDITOR, open_document, published, uri_of

PROGRAM = "DIM total = 0\ntotal = target + 1\nPRINT total\n"  # target: declared by the configuration file


def tell(client: LanguageClient, path: Path, change: types.FileChangeType) -> None:
    """What an editor watching files says when ``path`` changed on disk."""
    client.workspace_did_change_watched_files(
        types.DidChangeWatchedFilesParams(changes=[types.FileEvent(uri=uri_of(path), type=change)])
    )


def codes(diagnostics: list[types.Diagnostic]) -> list[str]:
    return [str(diagnostic.code) for diagnostic in diagnostics]


def test_programs_and_paired_files_are_watched_in_any_letter_case():
    assert globs("<name>.cfg") == ["**/*.[mM][nN][tT]", "**/*.[cC][fF][gG]"]
    assert globs("setup_<name>.txt") == ["**/*.[mM][nN][tT]", "**/[sS][eE][tT][uU][pP]_*.[tT][xX][tT]"]
    assert globs("") == ["**/*.[mM][nN][tT]"]  # no configuration files


@pytest_lsp.fixture(config=EDITOR)
async def watching(lsp_client: LanguageClient):
    """A client that pushes diagnostics and watches files for the server (as Neovim 0.9+ does)."""
    capabilities = client_capabilities("neovim@v0.7.0")
    capabilities.workspace.did_change_watched_files = types.DidChangeWatchedFilesClientCapabilities(
        dynamic_registration=True
    )
    params = types.InitializeParams(capabilities=capabilities, initialization_options={"mint": {"debounceMs": 0}})
    await lsp_client.initialize_session(params)
    yield
    await lsp_client.shutdown_session()


@pytest.mark.asyncio
async def test_a_watching_client_is_asked_to_watch_and_its_news_re_check(watching, tmp_path):
    for _ in range(100):
        if watching.registrations:
            break
        await asyncio.sleep(0.05)
    [registration] = watching.registrations
    assert registration.method == types.WORKSPACE_DID_CHANGE_WATCHED_FILES
    config, other = tmp_path / "APP.CFG", tmp_path / "other.cfg"
    config.write_text("REM nothing yet\n", encoding="utf-8")
    other.write_text("DIM target = 3\n", encoding="utf-8")
    uri = uri_of(tmp_path / "app.mnt")
    assert "E3001" in codes(await open_document(watching, uri, PROGRAM))
    tell(watching, other, types.FileChangeType.Changed)  # a file the program does not read: nothing to do
    config.write_text("DIM target = 3\n", encoding="utf-8")
    tell(watching, config, types.FileChangeType.Changed)
    assert "E3001" not in codes(await asyncio.wait_for(published(watching, uri), 10))


@pytest.mark.asyncio
async def test_a_configuration_file_created_beside_the_program_is_read(watching, tmp_path):
    uri = uri_of(tmp_path / "app.mnt")
    assert "E3001" in codes(await open_document(watching, uri, PROGRAM))
    config = tmp_path / "app.cfg"
    config.write_text("DIM target = 3\n", encoding="utf-8")
    tell(watching, config, types.FileChangeType.Created)
    assert "E3001" not in codes(await asyncio.wait_for(published(watching, uri), 10))


@pytest.mark.asyncio
async def test_without_a_watching_client_the_server_looks_itself(neovim, tmp_path):
    config = tmp_path / "app.cfg"
    config.write_text("REM nothing yet\n", encoding="utf-8")
    uri = uri_of(tmp_path / "app.mnt")
    assert "E3001" in codes(await open_document(neovim, uri, PROGRAM))
    await asyncio.sleep(1.5)  # the server has looked at the file once
    config.write_text("DIM target = 3\n", encoding="utf-8")
    assert "E3001" not in codes(await asyncio.wait_for(published(neovim, uri), 10))


@pytest.mark.asyncio
async def test_a_new_pairing_is_watched_instead(watching, tmp_path):
    while not watching.registrations:
        await asyncio.sleep(0.05)
    watching.workspace_did_change_configuration(
        types.DidChangeConfigurationParams(settings={"mint": {"configPairing": "<name>.ini"}})
    )
    for _ in range(200):
        if watching.registrations and "**/*.[iI][nN][iI]" in _globs(watching.registrations[0]):
            break
        await asyncio.sleep(0.05)
    [registration] = watching.registrations
    assert _globs(registration) == ["**/*.[mM][nN][tT]", "**/*.[iI][nN][iI]"]


def _globs(registration: types.Registration) -> list[str]:
    return [watcher["globPattern"] for watcher in registration.register_options["watchers"]]
