"""Fix all (``source.fixAll``, VS Code's ``editor.codeActionsOnSave``): the program as ``mint check --fix``
writes it, every safe fix made and the unsafe ones left for the author to choose."""

from __future__ import annotations

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import LanguageClient

from tests.lsp.conftest import EDITOR, VS_CODE, document, open_document, uri_of
from tests.lsp.test_quick_fixes import applied

pytestmark = pytest.mark.asyncio

WHOLE = types.Range(start=types.Position(line=0, character=0), end=types.Position(line=0, character=0))


async def fix_all(client, uri: str) -> list[types.CodeAction]:
    context = types.CodeActionContext(diagnostics=[], only=[types.CodeActionKind.SourceFixAll])
    found = await client.text_document_code_action_async(
        types.CodeActionParams(text_document=document(uri), range=WHOLE, context=context)
    )
    return list(found or [])


async def test_the_safe_fixes_are_made_and_the_unsafe_one_is_left(client, tmp_path):
    # Mint assigns with '=' alone (000:1274-1282) and writes 'not equal to' <> (000:1262): both rewrites keep the
    # meaning. '&' is Mint's bitwise AND (000:1286-1289): a comma instead prints the items one after the other
    # (000:15299-15302), which may not be what was meant, so that fix waits for the author.
    text = 'DIM count = 0\nDIM b = 2\ncount += 1\nIF count != 2 THEN PRINT count\nPRINT "b is " & b\n'
    uri = uri_of(tmp_path / "cell.mnt")
    await open_document(client, uri, text)
    [action] = await fix_all(client, uri)
    assert action.kind.startswith(types.CodeActionKind.SourceFixAll)
    assert applied(text, action, uri) == (
        'DIM count = 0\nDIM b = 2\ncount = count + 1\nIF count <> 2 THEN PRINT count\nPRINT "b is " & b\n'
    )


async def test_a_request_naming_no_kind_is_not_given_it(client, tmp_path):
    # a lightbulb's request, sent at every cursor move: fixing every finding is not what it shows
    text = "DIM count = 0\ncount += 1\n"
    uri = uri_of(tmp_path / "cell.mnt")
    await open_document(client, uri, text)
    context = types.CodeActionContext(diagnostics=[])
    found = await client.text_document_code_action_async(
        types.CodeActionParams(text_document=document(uri), range=WHOLE, context=context)
    )
    assert not [action for action in found if str(action.kind).startswith(types.CodeActionKind.SourceFixAll)]


async def test_nothing_is_offered_where_only_unsafe_fixes_are(client, tmp_path):
    text = 'DIM b = 2\nPRINT "b is " & b\n'
    uri = uri_of(tmp_path / "cell.mnt")
    await open_document(client, uri, text)
    assert await fix_all(client, uri) == []


async def test_a_label_written_with_a_colon_is_fixed_with_the_rest(client, tmp_path):
    # a label is #name first on its line (000:1843-1844): 'Init:' followed by nothing is written '#Init' alone
    text = "Init:\nDIM n = 0\nn += 1\nIF n < 3 THEN GOTO Init\n"
    uri = uri_of(tmp_path / "cell.mnt")
    await open_document(client, uri, text)
    [action] = await fix_all(client, uri)
    assert applied(text, action, uri) == "#Init\nDIM n = 0\nn = n + 1\nIF n < 3 THEN GOTO Init\n"


@pytest_lsp.fixture(config=EDITOR)
async def started(lsp_client: LanguageClient):
    """The client, with the server's answer to ``initialize`` (``result``)."""
    lsp_client.result = await lsp_client.initialize_session(VS_CODE)
    yield
    await lsp_client.shutdown_session()


async def test_the_server_says_it_offers_fix_all(started):
    # VS Code asks on save only the servers that list the kind its setting names
    kinds = started.result.capabilities.code_action_provider.code_action_kinds
    assert any(str(kind).startswith(types.CodeActionKind.SourceFixAll) for kind in kinds)
