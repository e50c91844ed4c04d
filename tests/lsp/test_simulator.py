"""Run in simulator: the code lens on programs and the command that runs a program in mint-run."""

from __future__ import annotations

from pathlib import Path

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from tests.lsp.conftest import open_document, uri_of

PROGRAM = 'RESET.0\nMOVER.0 = 1000 : GO.0\nPAUSE IDLE.0\nPRINT "at ", POS.0, " with ", gain\n'
CONFIGURATION = "DIM gain = 7\n"


async def lenses(client: LanguageClient, uri: str) -> list[types.CodeLens]:
    """The run lenses of ``uri`` (the reference counts are lenses too, without a command until resolved)."""
    found = await client.text_document_code_lens_async(
        types.CodeLensParams(text_document=types.TextDocumentIdentifier(uri=uri))
    )
    return [lens for lens in found or [] if lens.command is not None]


@pytest.mark.asyncio
async def test_a_program_gets_a_run_lens_and_its_configuration_file_does_not(
    client: LanguageClient, tmp_path: Path
) -> None:
    program, configuration = tmp_path / "cell.mnt", tmp_path / "cell.cfg"
    program.write_text(PROGRAM, encoding="utf-8")
    configuration.write_text(CONFIGURATION, encoding="utf-8")
    await open_document(client, uri_of(program), PROGRAM)
    await open_document(client, uri_of(configuration), CONFIGURATION)
    (lens,) = await lenses(client, uri_of(program))
    assert lens.command is not None and lens.command.command == "mint.simulateFile"
    assert list(lens.command.arguments or ()) == [uri_of(program)]
    assert await lenses(client, uri_of(configuration)) == []


@pytest.mark.asyncio
async def test_the_command_runs_the_program_with_its_configuration(client: LanguageClient, tmp_path: Path) -> None:
    program = tmp_path / "cell.mnt"
    program.write_text(PROGRAM, encoding="utf-8")
    (tmp_path / "cell.cfg").write_text(CONFIGURATION, encoding="utf-8")
    await open_document(client, uri_of(program), PROGRAM)
    report = await client.workspace_execute_command_async(
        types.ExecuteCommandParams(command="mint.simulateFile", arguments=[uri_of(program)])
    )
    assert report["stopped"] == "end" and report["axes"]["0"]["pos"] == 1000
    assert any("at 1000 with 7" in message.message for message in client.log_messages)
    assert any(message.message.startswith("Simulation end after") for message in client.messages)


@pytest.mark.asyncio
async def test_asked_for_the_configuration_file_it_runs_the_program_it_configures(
    client: LanguageClient, tmp_path: Path
) -> None:
    (tmp_path / "cell.mnt").write_text(PROGRAM, encoding="utf-8")
    configuration = tmp_path / "cell.cfg"
    configuration.write_text(CONFIGURATION, encoding="utf-8")
    report = await client.workspace_execute_command_async(
        types.ExecuteCommandParams(command="mint.simulateFile", arguments=[uri_of(configuration)])
    )
    assert report["stopped"] == "end" and report["axes"]["0"]["pos"] == 1000
    assert any("at 1000 with 7" in message.message for message in client.log_messages)


@pytest.mark.asyncio
async def test_a_failing_program_is_reported_as_an_error(client: LanguageClient, tmp_path: Path) -> None:
    program = tmp_path / "fails.mnt"
    text = "DIM a = 0\nPRINT 1 / a\n"
    program.write_text(text, encoding="utf-8")
    await open_document(client, uri_of(program), text)
    report = await client.workspace_execute_command_async(
        types.ExecuteCommandParams(command="mint.simulateFile", arguments=[uri_of(program)])
    )
    assert report["stopped"] == "error" and report["err"] == 2021
    shown = [message for message in client.messages if message.message.startswith("Simulation error")]
    assert shown and shown[-1].type == types.MessageType.Error
