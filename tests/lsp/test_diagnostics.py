"""Diagnostics: pushed on open and on every (debounced) edit, pulled on request, paired with the .cfg."""

from __future__ import annotations

import asyncio

import pytest
from lsprotocol import types

from tests.lsp.conftest import change, corpus, document, open_document, published, uri_of

pytestmark = pytest.mark.asyncio


def errors(diagnostics: list[types.Diagnostic]) -> set[str]:
    return {d.code for d in diagnostics if d.severity == types.DiagnosticSeverity.Error}


async def test_a_manual_example_has_no_errors(client, tmp_path):
    uri = uri_of(tmp_path / "xy.mnt")
    diagnostics = await open_document(client, uri, corpus("ch01_l0144_xy_example.mnt"))
    assert errors(diagnostics) == set()


async def test_mint_error_number_and_title(client, tmp_path):
    uri = uri_of(tmp_path / "undeclared.mnt")
    diagnostics = await open_document(client, uri, "DIM a\na = b + 1\n")
    [error] = [d for d in diagnostics if d.code == "E3001"]
    assert error.message.startswith("Variable undefined, use DIM")
    assert error.severity == types.DiagnosticSeverity.Error
    assert error.source == "mint"
    assert error.range == types.Range(
        start=types.Position(line=1, character=4), end=types.Position(line=1, character=5)
    )


async def test_edits_break_and_repair_a_file(client, tmp_path):
    uri = uri_of(tmp_path / "menu.mnt")
    text = corpus("ch03_l0815_main_menu_inkey.mnt")
    assert errors(await open_document(client, uri, text)) == set()
    change(client, uri, 2, ((14, 0), (14, 4)), "ENDW")  # ENDL -> ENDW: the LOOP is never closed
    assert "E2012" in errors(await published(client, uri))
    change(client, uri, 3, ((14, 0), (14, 4)), "ENDL")
    assert errors(await published(client, uri)) == set()


async def test_typing_is_debounced_into_one_publication(client, tmp_path):
    """Keys typed within the pause give one publication, of the last version. The pause is a second here,
    so that a loaded machine cannot split keys sent back to back (20 ms did, once)."""
    client.workspace_did_change_configuration(
        types.DidChangeConfigurationParams(settings={"mint": {"debounceMs": 1000}})
    )
    uri = uri_of(tmp_path / "typing.mnt")
    await open_document(client, uri, "DIM a\n")
    for version, character in enumerate("a = 1", start=2):
        change(client, uri, version, ((1, version - 2), (1, version - 2)), character)
    publication = await client.wait_for_notification(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    while publication.version == 1:  # the new setting also republishes what is open
        publication = await client.wait_for_notification(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    assert (publication.uri, publication.version) == (uri, 6)
    assert errors(publication.diagnostics) == set()
    pulled = await client.text_document_diagnostic_async(types.DocumentDiagnosticParams(text_document=document(uri)))
    assert errors(pulled.items) == set()


async def test_pull_diagnostics(client, tmp_path):
    uri = uri_of(tmp_path / "pull.mnt")
    await open_document(client, uri, "FOR i = 1 TO 3\n")
    report = await client.text_document_diagnostic_async(types.DocumentDiagnosticParams(text_document=document(uri)))
    assert "E3001" in {d.code for d in report.items}
    assert report.kind == "full"


async def test_configuration_file_beside_the_program(client, tmp_path):
    (tmp_path / "machine.cfg").write_text("DEFINE fast = 500\nDIM counter\n", encoding="utf-8")
    uri = uri_of(tmp_path / "machine.mnt")
    assert errors(await open_document(client, uri, "counter = fast\n")) == set()
    lonely = uri_of(tmp_path / "lonely.mnt")
    assert "E3001" in {d.code for d in await open_document(client, lonely, "counter = 1\n")}


async def test_the_configuration_file_is_found_whatever_the_case_of_its_name(client, tmp_path):
    (tmp_path / "app.cfg").write_text("DIM counter\n", encoding="utf-8")
    assert errors(await open_document(client, uri_of(tmp_path / "APP.MNT"), "counter = 1\n")) == set()


async def test_editing_the_configuration_refreshes_the_program(client, tmp_path):
    (tmp_path / "cell.cfg").write_text("DIM counter\n", encoding="utf-8")
    program, config = uri_of(tmp_path / "cell.mnt"), uri_of(tmp_path / "cell.cfg")
    assert errors(await open_document(client, program, "counter = 1\n")) == set()
    await open_document(client, config, "DIM counter\n")
    change(client, config, 2, ((0, 4), (0, 11)), "other")

    async def program_breaks() -> None:  # the latest diagnostics pytest-lsp recorded for the program
        while "E3001" not in errors(client.diagnostics.get(program, [])):
            await asyncio.sleep(0.02)

    await asyncio.wait_for(program_breaks(), timeout=10)


async def test_controller_setting_changes_the_checks(client, tmp_path):
    uri = uri_of(tmp_path / "outputs.mnt")
    assert errors(await open_document(client, uri, "OUT20 = 1\n")) == set()  # NextMove PCI: outputs 0 to 35
    client.workspace_did_change_configuration(
        types.DidChangeConfigurationParams(settings={"mint": {"controller": "mintdrive"}})
    )
    assert errors(await published(client, uri)) == {"E0008"}  # MintDrive: outputs 0 to 8
