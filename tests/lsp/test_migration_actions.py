"""v3 words in a file: "Replace v3 keywords" anywhere, the whole migration only in a v3 file, confirmed.

The v4 program below is issue 16's: its only v3 word is ``HMSPEED``, and the
whole migration used to add DIMs for its macros and its misspelt variable,
rename ERL to ERL_u and add AXES with prologue notes. Expected edits are
worked out by hand from the v4 guide's entry for HMSPEED ("replaced by
HOMESPEED").
"""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from tests.lsp.conftest import document, open_document, published, uri_of

pytestmark = pytest.mark.asyncio
MIGRATE, REPLACE = "Migrate this file to Mint v4", "Replace v3 keywords"

V4_PROGRAM = """\
DEFINE xAxis = 0
DEFINE zAxis = 2
DIM count = 0
HMSPEED[xAxis, zAxis] = 20, 10
LOOP
  countr = count + 1
  IF count > 10 THEN EXIT
ENDL
END
#ONERROR
  PRINT "error at line ", ERL
RETURN
"""


async def source_actions(client: LanguageClient, uri: str) -> dict[str, types.CodeAction]:
    start = types.Position(line=0, character=0)
    found = await client.text_document_code_action_async(
        types.CodeActionParams(
            text_document=document(uri),
            range=types.Range(start=start, end=start),
            context=types.CodeActionContext(diagnostics=[], only=[types.CodeActionKind.Source]),
        )
    )
    return {action.title: action for action in found or []}


def edits_of(edit: types.WorkspaceEdit) -> dict[str, list[types.TextEdit]]:
    """The text edits per document, whether sent as ``changes`` or ``documentChanges``."""
    if edit.changes is not None:
        return {uri: list(edits) for uri, edits in edit.changes.items()}
    return {change.text_document.uri: list(change.edits) for change in edit.document_changes or []}


async def test_a_v4_file_gets_only_its_v3_words_replaced(client, tmp_path):
    uri = uri_of(tmp_path / "axes.mnt")
    await open_document(client, uri, V4_PROGRAM)
    offered = await source_actions(client, uri)
    assert set(offered) == {REPLACE}
    assert offered[REPLACE].kind == "source.replaceV3Keywords" and offered[REPLACE].edit is None
    resolved = await client.code_action_resolve_async(offered[REPLACE])
    [edit] = resolved.edit.changes[uri]
    assert edit.new_text == "HOMESPEED"
    assert edit.range == types.Range(
        start=types.Position(line=3, character=0), end=types.Position(line=3, character=len("HMSPEED"))
    )


async def test_a_rename_the_v4_checker_rejects_is_left_out(client, tmp_path):
    uri = uri_of(tmp_path / "inputs.mnt")
    text = "HMSPEED.0 = 2\nEND\n#FASTPOS\nRETURN\n#FASTIN\nRETURN\n"  # #FASTIN twice would be E3004
    await open_document(client, uri, text)
    resolved = await client.code_action_resolve_async((await source_actions(client, uri))[REPLACE])
    assert [edit.new_text for edit in resolved.edit.changes[uri]] == ["HOMESPEED"]


async def test_a_v3_file_is_migrated_with_its_configuration_after_confirmation(client, tmp_path):
    program, config = tmp_path / "app.mnt", tmp_path / "app.cfg"
    config.write_text("REM setup\nSCALE.0 = 1000\nHMSPEED.0 = 5\n", encoding="utf-8")
    uri = uri_of(program)
    await open_document(client, uri, 'REM v3 program\nHMSPEED.0 = 10\nPRINT "done"\n')
    offered = await source_actions(client, uri)
    assert set(offered) == {REPLACE, MIGRATE}  # no scalar DIM, no v4-only keyword: a v3 file
    resolved = await client.code_action_resolve_async(offered[MIGRATE])
    [annotation] = resolved.edit.change_annotations.values()
    assert annotation.needs_confirmation
    for change in resolved.edit.document_changes:
        assert all(edit.annotation_id in resolved.edit.change_annotations for edit in change.edits)
    edits = edits_of(resolved.edit)
    assert [edit.new_text for edit in edits[uri]] == ["HOMESPEED.0 = 10\n"]
    # every axis keyword of the configuration names its axis, so no AXES line is needed (M-AXES)
    assert {edit.new_text for edit in edits[uri_of(config)]} == {"HOMESPEED.0 = 5\n"}


async def test_a_client_without_annotations_gets_the_plain_edit(neovim, tmp_path):
    uri = uri_of(tmp_path / "old.mnt")
    await open_document(neovim, uri, "REM limits\nHMSPEED.0 = 2\n")
    resolved = await neovim.code_action_resolve_async((await source_actions(neovim, uri))[MIGRATE])
    assert resolved.edit.change_annotations is None
    [edit] = resolved.edit.changes[uri]  # with no configuration file, AXES goes before the first move
    assert edit.new_text.endswith("HOMESPEED.0 = 2\n") and "HMSPEED" not in edit.new_text


async def test_the_v3_dialect_setting_offers_the_migration(client, tmp_path):
    uri = uri_of(tmp_path / "legacy.mnt")
    await open_document(client, uri, "DIM a\na = 1\nHMSPEED.0 = 10\n")
    assert set(await source_actions(client, uri)) == {REPLACE}  # a scalar DIM: v4 for the detection
    client.workspace_did_change_configuration(types.DidChangeConfigurationParams(settings={"mint": {"dialect": "v3"}}))
    await published(client, uri)
    assert set(await source_actions(client, uri)) == {MIGRATE}  # v3 words are no error in v3


async def test_v4_code_without_v3_words_gets_neither(client, tmp_path):
    uri = uri_of(tmp_path / "new.mnt")
    await open_document(client, uri, "HOMESPEED.0 = 2\n")
    assert await source_actions(client, uri) == {}


async def test_an_action_offered_on_an_older_version_is_not_resolved(client, tmp_path):
    uri = uri_of(tmp_path / "typing.mnt")
    await open_document(client, uri, "HMSPEED.0 = 2\n")
    action = (await source_actions(client, uri))[REPLACE]
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(
            text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=2),
            content_changes=[types.TextDocumentContentChangeWholeDocument(text="HOMESPEED.0 = 2\n")],
        )
    )
    assert (await client.code_action_resolve_async(action)).edit is None


async def test_a_configuration_file_alone_gets_its_v3_words_replaced(client, tmp_path):
    uri = uri_of(tmp_path / "alone.cfg")
    await open_document(client, uri, "SCALE.0 = 1000\nHMSPEED.0 = 5\n")
    offered = await source_actions(client, uri)
    assert set(offered) == {REPLACE}  # the migration starts from a program
    resolved = await client.code_action_resolve_async(offered[REPLACE])
    assert [edit.new_text for edit in resolved.edit.changes[uri]] == ["HOMESPEED"]
