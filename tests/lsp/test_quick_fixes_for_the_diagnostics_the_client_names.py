"""Quick fixes for the diagnostics a client names in its request, wherever its cursor stands on their line.

Neovim 0.7 asks for code actions at the cursor (an empty range) and names every diagnostic of the cursor's
line in the request's context (``vim.lsp.buf.code_action``: ``get_line_diagnostics``); the README promises
"In the editor every diagnostic has a quick fix" for Neovim 0.7 and later as for VS Code.
"""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import document, open_document, uri_of

pytestmark = pytest.mark.asyncio


async def titles_at(client, uri: str, cursor: types.Position, named: list[types.Diagnostic]) -> set[str]:
    context = types.CodeActionContext(diagnostics=named, only=[types.CodeActionKind.QuickFix])
    found = await client.text_document_code_action_async(
        types.CodeActionParams(
            text_document=document(uri), range=types.Range(start=cursor, end=cursor), context=context
        )
    )
    return {action.title for action in found}


async def test_a_diagnostic_named_in_the_context_has_its_fixes_with_the_cursor_at_the_start_of_its_line(
    neovim, tmp_path
):
    # DIM spare is never used (W103, at 'spare', column 5); the cursor at column 1 of that line
    text = "DIM spare\nDIM speeds(4)\nspeeds(1) = 10\nPRINT speeds(1)\nEND\n"
    uri = uri_of(tmp_path / "line.mnt")
    diagnostics = await open_document(neovim, uri, text)
    on_the_line = [diagnostic for diagnostic in diagnostics if diagnostic.range.start.line == 0]
    assert [str(diagnostic.code) for diagnostic in on_the_line] == ["W103"]
    titles = await titles_at(neovim, uri, types.Position(line=0, character=0), on_the_line)
    assert "Ignore W103 on this line" in titles


async def test_a_diagnostic_the_client_does_not_name_is_offered_only_where_the_range_meets_it(neovim, tmp_path):
    # undeclared 'x' (E3001) is at column 7; nothing named, the cursor at column 1: no fix for it
    text = "PRINT x\nEND\n"
    uri = uri_of(tmp_path / "unnamed.mnt")
    await open_document(neovim, uri, text)
    assert await titles_at(neovim, uri, types.Position(line=0, character=0), []) == set()


async def test_a_diagnostic_named_on_another_line_is_not_offered(neovim, tmp_path):
    # a client that names every diagnostic of the file gets the fixes of the cursor's line only
    text = "DIM spare\nDIM other\nEND\n"
    uri = uri_of(tmp_path / "lines.mnt")
    diagnostics = await open_document(neovim, uri, text)
    assert [str(d.code) for d in diagnostics] == ["W103", "W103"]
    cursor = types.Position(line=1, character=0)
    context = types.CodeActionContext(diagnostics=diagnostics, only=[types.CodeActionKind.QuickFix])
    found = await neovim.text_document_code_action_async(
        types.CodeActionParams(
            text_document=document(uri), range=types.Range(start=cursor, end=cursor), context=context
        )
    )
    assert [(action.title, [edit.range.start.line for edit in action.edit.changes[uri]]) for action in found] == [
        ("Ignore W103 on this line", [1])
    ]
