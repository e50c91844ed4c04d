"""The server reads a document's settings file (``mint.toml``, ``[tool.mint]``) as ``mint check`` does; the
editor's own settings win over it."""

from __future__ import annotations

import asyncio

import pytest
from lsprotocol import types

from tests.lsp.conftest import open_document, published, uri_of

pytestmark = pytest.mark.asyncio

OUTPUT_20 = "OUT20 = 1\n"  # NextMove PCI has outputs 0 to 35, MintDrive 0 to 8: error 8 on MintDrive (v4 guide)


def codes(diagnostics: list[types.Diagnostic]) -> set[str]:
    return {str(d.code) for d in diagnostics}


def error_numbers(diagnostics: list[types.Diagnostic]) -> set[int]:
    """The controller's error numbers, however many digits the code is written with."""
    return {int(str(d.code)[1:]) for d in diagnostics if str(d.code).startswith("E")}


async def test_the_controller_of_the_settings_file_applies(client, tmp_path):
    (tmp_path / "mint.toml").write_text('controller = "mintdrive"\n', encoding="utf-8")
    (tmp_path / "cells").mkdir()
    assert error_numbers(await open_document(client, uri_of(tmp_path / "cells" / "out.mnt"), OUTPUT_20)) == {8}


async def test_a_pyproject_tool_mint_table_applies_and_ignores_codes(client, tmp_path):
    (tmp_path / "pyproject.toml").write_text('[project]\nname = "x"\n\n[tool.mint]\nignore = ["W103"]\n', "utf-8")
    assert "W103" not in codes(await open_document(client, uri_of(tmp_path / "spare.mnt"), "DIM spare\n"))


async def test_per_file_ignores_apply_to_the_files_their_glob_matches(client, tmp_path):
    (tmp_path / "mint.toml").write_text('[per-file-ignores]\n"legacy/*.mnt" = ["W103"]\n', encoding="utf-8")
    (tmp_path / "legacy").mkdir()
    assert "W103" not in codes(await open_document(client, uri_of(tmp_path / "legacy" / "a.mnt"), "DIM spare\n"))
    assert "W103" in codes(await open_document(client, uri_of(tmp_path / "b.mnt"), "DIM spare\n"))


async def test_the_settings_files_pairing_names_the_configuration(client, tmp_path):
    (tmp_path / "mint.toml").write_text('config-pairing = "setup_<name>.txt"\n', encoding="utf-8")
    (tmp_path / "setup_press.txt").write_text("DIM counter\n", encoding="utf-8")
    assert error_numbers(await open_document(client, uri_of(tmp_path / "press.mnt"), "counter = 1\n")) == set()


async def test_the_editors_setting_wins_over_the_settings_file(client, tmp_path):
    (tmp_path / "mint.toml").write_text('controller = "mintdrive"\n', encoding="utf-8")
    uri = uri_of(tmp_path / "out.mnt")
    assert error_numbers(await open_document(client, uri, OUTPUT_20)) == {8}
    client.workspace_did_change_configuration(
        types.DidChangeConfigurationParams(settings={"mint": {"controller": "nextmove-pci"}})
    )
    assert error_numbers(await published(client, uri)) == set()


async def test_a_setting_the_editor_sends_as_null_gives_way_to_the_settings_file_again(client, tmp_path):
    # VS Code sends null for a setting the user has not set: its default must not hide the project's mint.toml
    (tmp_path / "mint.toml").write_text('controller = "mintdrive"\n', encoding="utf-8")
    uri = uri_of(tmp_path / "out.mnt")
    client.workspace_did_change_configuration(
        types.DidChangeConfigurationParams(settings={"mint": {"controller": "nextmove-pci"}})
    )
    assert error_numbers(await open_document(client, uri, OUTPUT_20)) == set()
    client.workspace_did_change_configuration(
        types.DidChangeConfigurationParams(settings={"mint": {"controller": None}})
    )
    # the check of the open document before the change may still be on its way: wait for the one after it
    async with asyncio.timeout(10):
        while error_numbers(await published(client, uri)) != {8}:
            pass


async def test_a_broken_settings_file_leaves_the_editors_settings(client, tmp_path):
    (tmp_path / "mint.toml").write_text('controller = "mintdrive"\nselect = ["X9"]\n', encoding="utf-8")
    assert error_numbers(await open_document(client, uri_of(tmp_path / "out.mnt"), OUTPUT_20)) == set()


async def test_run_in_simulator_uses_the_settings_files_controller_and_pairing(client, tmp_path):
    (tmp_path / "mint.toml").write_text('controller = "mintdrive"\nconfig-pairing = "<name>_setup.mnc"\n', "utf-8")
    (tmp_path / "out_setup.mnc").write_text("DIM level = 1\n", encoding="utf-8")  # undeclared without it: C3001
    program = tmp_path / "out.mnt"
    program.write_text("OUT10 = level\n", encoding="utf-8")  # MintDrive has outputs 0 to 8, NextMove PCI 0 to 11
    report = await client.workspace_execute_command_async(
        types.ExecuteCommandParams(command="mint.simulateFile", arguments=[uri_of(program)])
    )
    assert report["stopped"] == "error"
    assert "R0008" in report["message"]
