"""A real ``mint-lsp`` over stdio for every test, and helpers to drive it like an editor."""

from __future__ import annotations

import asyncio
import sys
from pathlib import Path

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import ClientServerConfig, LanguageClient, client_capabilities, make_test_lsp_client

CORPUS = Path(__file__).parents[1] / "corpus" / "v4" / "valid"
SERVER = [sys.executable, "-m", "mintlang.lsp"]


def editor_client() -> LanguageClient:
    """pytest-lsp's client, granting and withdrawing the server's registrations as an editor does (it keeps
    those in force in ``registrations``): a request it has no handler for fails the test."""
    client = make_test_lsp_client()
    client.registrations = []

    @client.feature(types.CLIENT_REGISTER_CAPABILITY)
    def register(params: types.RegistrationParams) -> None:
        client.registrations.extend(params.registrations)

    @client.feature(types.CLIENT_UNREGISTER_CAPABILITY)
    def unregister(params: types.UnregistrationParams) -> None:
        gone = {(old.id, old.method) for old in params.unregisterations}
        client.registrations[:] = [kept for kept in client.registrations if (kept.id, kept.method) not in gone]

    return client


EDITOR = ClientServerConfig(server_command=SERVER, client_factory=editor_client)


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line("markers", "slow: runs for tens of seconds (CI runs it; -m 'not slow' skips it)")


VS_CODE = types.InitializeParams(
    capabilities=client_capabilities("visual-studio-code"), initialization_options={"mint": {"debounceMs": 20}}
)


@pytest_lsp.fixture(config=EDITOR)
async def client(lsp_client: LanguageClient):
    await lsp_client.initialize_session(VS_CODE)
    yield
    await lsp_client.shutdown_session()


@pytest_lsp.fixture(config=EDITOR, scope="module")
async def shared_client(lsp_client: LanguageClient):
    """``client``, one server for a module's tests marked ``SHARED``: the cases of a parametrized test
    that only asks (each case opens its own document and changes no setting), for which starting a
    server was most of the time."""
    await lsp_client.initialize_session(VS_CODE)
    yield
    await lsp_client.shutdown_session()


SHARED = pytest.mark.asyncio(loop_scope="module")  # the loop ``shared_client`` runs in


@pytest_lsp.fixture(config=EDITOR)
async def neovim(lsp_client: LanguageClient):
    """A client with Neovim 0.7's capabilities (diagnostics pushed, no window/showDocument, no file watching),
    checking every edit at once."""
    params = types.InitializeParams(
        capabilities=client_capabilities("neovim@v0.7.0"), initialization_options={"mint": {"debounceMs": 0}}
    )
    await lsp_client.initialize_session(params)
    yield
    await lsp_client.shutdown_session()


def corpus(name: str) -> str:
    return (CORPUS / name).read_text(encoding="utf-8")


def uri_of(path: Path) -> str:
    return path.resolve().as_uri()


async def open_document(client: LanguageClient, uri: str, text: str, version: int = 1) -> list[types.Diagnostic]:
    """Open ``text`` and return the diagnostics the server publishes for it."""
    client.text_document_did_open(
        types.DidOpenTextDocumentParams(
            text_document=types.TextDocumentItem(uri=uri, language_id="mint", version=version, text=text)
        )
    )
    return await published(client, uri)


PUBLISHED_WITHIN_S = 60.0  # a hang guard, not a timing: a server that never publishes fails the test


async def published(client: LanguageClient, uri: str) -> list[types.Diagnostic]:
    """Wait for the next diagnostics of ``uri``."""
    async with asyncio.timeout(PUBLISHED_WITHIN_S):
        while True:
            params = await client.wait_for_notification(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
            if params.uri == uri:
                return list(params.diagnostics)


Place = tuple[int, int]  # line, character


def change(client: LanguageClient, uri: str, version: int, where: tuple[Place, Place], text: str) -> None:
    """An incremental edit: replace the range ``where`` with ``text``."""
    start, end = where
    edit_range = types.Range(
        start=types.Position(line=start[0], character=start[1]), end=types.Position(line=end[0], character=end[1])
    )
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(
            text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=version),
            content_changes=[types.TextDocumentContentChangePartial(range=edit_range, text=text)],
        )
    )


def position(text: str, needle: str, shift: int = 0) -> types.Position:
    """The position of the first ``needle`` in ``text`` (ASCII), moved ``shift`` characters right."""
    offset = text.index(needle) + shift
    line = text.count("\n", 0, offset)
    return types.Position(line=line, character=offset - (text.rfind("\n", 0, offset) + 1))


def document(uri: str) -> types.TextDocumentIdentifier:
    return types.TextDocumentIdentifier(uri=uri)


def units(text: str, encoding: str) -> int:
    """Code units of ``text`` in an LSP position encoding, as Python's codecs count them: the tests'
    reference, written apart from the server's own conversions."""
    if encoding == types.PositionEncodingKind.Utf8:
        return len(text.encode("utf-8"))
    if encoding == types.PositionEncodingKind.Utf16:
        return len(text.encode("utf-16-le")) // 2
    return len(text)
