"""``mint.applicationFiles``: the program and configuration file a file goes with, as the server pairs them for its
checks, so that an editor runs, debugs and opens files as Mint by the server's pairing rather than one of its own:
the project's settings file (``config-pairing``, ``config``) under the editor's ``mint.configPairing``; and the
dialect the server reads the program in, which the editor runs it in."""

from __future__ import annotations

from pathlib import Path

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from tests.lsp.conftest import open_document, uri_of

pytestmark = pytest.mark.asyncio

NONE = {"program": None, "configuration": None, "dialect": None}


async def application(client: LanguageClient, path: Path) -> dict:
    return await client.workspace_execute_command_async(
        types.ExecuteCommandParams(command="mint.applicationFiles", arguments=[uri_of(path)])
    )


def files(tmp_path: Path, *names: str) -> list[Path]:
    for name in names:
        (tmp_path / name).write_text("DIM x\n", encoding="utf-8")
    return [tmp_path / name for name in names]


def pair(program: Path | None, configuration: Path | None, dialect: str = "v4") -> dict:
    """The answer for a file of this application; the dialect is the program's (none without one)."""
    return {
        "program": uri_of(program) if program else None,
        "configuration": uri_of(configuration) if configuration else None,
        "dialect": dialect if program else None,
    }


async def test_the_settings_files_pairing_names_a_programs_configuration(client, tmp_path):
    # the README's Pairing: config-pairing names <name>'s file beside the program; a.cfg is then nobody's
    (tmp_path / "mint.toml").write_text('config-pairing = "setup_<name>.cfg"\n', encoding="utf-8")
    program, setup, plain, lone = files(tmp_path, "a.mnt", "setup_a.cfg", "a.cfg", "setup_lone.cfg")
    assert await application(client, program) == pair(program, setup)
    assert await application(client, setup) == pair(program, setup)
    assert await application(client, plain) == NONE
    assert await application(client, lone) == NONE  # no lone.mnt beside it


async def test_a_program_without_its_configuration_file_has_none(client, tmp_path):
    (program,) = files(tmp_path, "a.mnt")
    assert await application(client, program) == pair(program, None)


async def test_the_editors_pairing_wins_over_the_settings_files(client, tmp_path):
    (tmp_path / "mint.toml").write_text('config-pairing = "setup_<name>.cfg"\n', encoding="utf-8")
    program, setup, plain = files(tmp_path, "a.mnt", "setup_a.cfg", "a.cfg")
    client.workspace_did_change_configuration(
        types.DidChangeConfigurationParams(settings={"mint": {"configPairing": "<name>.cfg"}})
    )
    assert await application(client, program) == pair(program, plain)
    assert await application(client, setup) == NONE
    client.workspace_did_change_configuration(
        types.DidChangeConfigurationParams(settings={"mint": {"configPairing": ""}})
    )
    assert await application(client, program) == pair(program, None)  # empty: programs have no configuration
    client.workspace_did_change_configuration(
        types.DidChangeConfigurationParams(settings={"mint": {"configPairing": None}})
    )
    assert await application(client, program) == pair(program, setup)  # unset again: the settings file's


async def test_the_settings_files_config_is_every_programs_configuration(client, tmp_path):
    # config names one file for every program, and pairing by name is then off (README, Configuration)
    (tmp_path / "mint.toml").write_text('config = "shared/line.cfg"\n', encoding="utf-8")
    program, beside = files(tmp_path, "a.mnt", "a.cfg")
    shared = tmp_path / "shared" / "line.cfg"
    # named outright, it is the program's even while missing: a run then says it cannot read it, as mint-run does
    assert await application(client, program) == pair(program, shared)
    assert await application(client, beside) == NONE
    shared.parent.mkdir()
    shared.write_text("DIM x\n", encoding="utf-8")
    assert await application(client, shared) == pair(None, shared)


async def test_names_match_whatever_their_case_and_the_exact_one_wins(client, tmp_path):
    program, configuration = files(tmp_path, "APP.MNT", "app.cfg")
    assert await application(client, program) == pair(program, configuration)
    assert await application(client, configuration) == pair(program, configuration)
    other, exact, upper = files(tmp_path, "press.mnt", "press.cfg", "PRESS.CFG")
    assert await application(client, upper) == NONE  # press.mnt runs press.cfg, written as the pattern writes it
    assert await application(client, exact) == pair(other, exact)


async def test_a_configuration_open_in_the_editor_but_not_saved_is_the_programs(client, tmp_path):
    (program,) = files(tmp_path, "a.mnt")
    unsaved = tmp_path / "a.cfg"
    await open_document(client, uri_of(unsaved), "DIM x\n")
    assert await application(client, program) == pair(program, unsaved)
    assert await application(client, unsaved) == pair(program, unsaved)


async def test_a_file_outside_the_disk_belongs_to_no_application(client):
    answer = await client.workspace_execute_command_async(
        types.ExecuteCommandParams(command="mint.applicationFiles", arguments=["untitled:Untitled-1"])
    )
    assert answer == NONE


async def test_the_answer_after_a_settings_change_follows_the_new_settings(client, tmp_path):
    # VS Code says only that the settings changed; the server asks for them (workspace/configuration), and an
    # editor that asks for a pairing at once, to open the files the new pattern pairs as Mint, gets the new one
    program, setup, plain = files(tmp_path, "a.mnt", "setup_a.cfg", "a.cfg")
    assert await application(client, program) == pair(program, plain)
    client.set_configuration({"configPairing": "setup_<name>.cfg"}, section="mint")
    client.workspace_did_change_configuration(types.DidChangeConfigurationParams(settings=None))
    assert await application(client, setup) == pair(program, setup)


MINTMT = "' a comment only MintMT has\nDim x\nx = 5\nPrint x\n"  # README, mint.dialect: a ' comment shows MintMT


async def test_the_dialect_is_the_one_the_server_reads_the_program_in(client, tmp_path):
    program, configuration = tmp_path / "mt.mnt", tmp_path / "mt.cfg"
    program.write_text(MINTMT, encoding="utf-8")
    configuration.write_text("DIM y\n", encoding="utf-8")
    (v4,) = files(tmp_path, "v4.mnt")
    assert await application(client, program) == pair(program, configuration, "v4")  # the default reads v4
    client.workspace_did_change_configuration(
        types.DidChangeConfigurationParams(settings={"mint": {"dialect": "auto"}})
    )
    assert await application(client, program) == pair(program, configuration, "mintmt")  # the text shows MintMT
    assert await application(client, configuration) == pair(program, configuration, "mintmt")  # its program's
    assert await application(client, v4) == pair(v4, None, "v4")


async def test_the_settings_files_dialect_applies_where_the_editor_sets_none(client, tmp_path):
    (tmp_path / "mint.toml").write_text('dialect = "mintmt"\n', encoding="utf-8")
    (program,) = files(tmp_path, "a.mnt")
    assert await application(client, program) == pair(program, None, "mintmt")
