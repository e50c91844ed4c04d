"""Quick fixes from the core's diagnostics (the v3 → v4 source actions: ``test_migration_actions``)."""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import document, open_document, published, uri_of

pytestmark = pytest.mark.asyncio


async def actions(client, uri, diagnostics, line) -> list[types.CodeAction]:
    where = types.Range(start=types.Position(line=line, character=0), end=types.Position(line=line, character=80))
    context = types.CodeActionContext(diagnostics=diagnostics)
    return list(
        await client.text_document_code_action_async(
            types.CodeActionParams(text_document=document(uri), range=where, context=context)
        )
    )


def only_edit(action: types.CodeAction, uri: str) -> types.TextEdit:
    [edit] = action.edit.changes[uri]
    return edit


async def test_declare_with_dim(client, tmp_path):
    uri = uri_of(tmp_path / "dim.mnt")
    diagnostics = await open_document(client, uri, "count = 1\n")
    [fix, ignore] = await actions(client, uri, diagnostics, 0)
    assert fix.title == "Declare 'count' with DIM"
    assert ignore.title == "Ignore E3001 on this line"  # every diagnostic can be silenced on its line
    assert fix.kind == types.CodeActionKind.QuickFix
    assert fix.diagnostics[0].code == "E3001"
    assert only_edit(fix, uri).new_text == "DIM count\n"


async def test_replace_a_v3_keyword(client, tmp_path):
    uri = uri_of(tmp_path / "v3.mnt")
    diagnostics = await open_document(client, uri, "HMSPEED = 2\n")
    fixes = [a for a in await actions(client, uri, diagnostics, 0) if a.kind == types.CodeActionKind.QuickFix]
    assert "Replace with HOMESPEED" in [a.title for a in fixes]


async def test_plain_quotes(client, tmp_path):
    uri = uri_of(tmp_path / "quotes.mnt")
    diagnostics = await open_document(client, uri, "PRINT “hello”\n")
    [fix] = [a for a in await actions(client, uri, diagnostics, 0) if a.title == "Replace with plain quotes"]
    assert {e.new_text for e in fix.edit.changes[uri]} == {'"'}


async def test_bracket_to_dot_hint(client, tmp_path):
    client.workspace_did_change_configuration(
        types.DidChangeConfigurationParams(settings={"mint": {"select": "E,W,I"}})
    )
    uri = uri_of(tmp_path / "dot.mnt")
    diagnostics = await open_document(client, uri, "SPEED[0] = 10\n")
    [fix] = [a for a in await actions(client, uri, diagnostics, 0) if a.title.startswith("Write")]
    assert only_edit(fix, uri).new_text == ".0"


async def test_v3_dialect_setting(client, tmp_path):
    uri = uri_of(tmp_path / "legacy.mnt")
    text = "HMSPEED.0 = 10\n\n"
    await open_document(client, uri, text)
    client.workspace_did_change_configuration(types.DidChangeConfigurationParams(settings={"mint": {"dialect": "v3"}}))
    assert not [d for d in await published(client, uri) if d.code == "E3007"]  # HMSPEED is a keyword in v3
    found = await client.text_document_completion_async(
        types.CompletionParams(text_document=document(uri), position=types.Position(line=1, character=0))
    )
    assert "Mint v3, abbreviation HS" in {item.detail for item in found.items if item.label == "HMSPEED"}
