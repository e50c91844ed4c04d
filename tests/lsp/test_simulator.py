"""Run in simulator: the code lens on programs, and the command that runs a program in mint-run, shows what it
printed where the user sees it, shows its progress and can be cancelled."""

from __future__ import annotations

import asyncio
from pathlib import Path

import pytest
from lsprotocol import types
from pygls.exceptions import JsonRpcException
from pygls.uris import to_fs_path
from pytest_lsp import LanguageClient

from tests.lsp.conftest import open_document, uri_of

PROGRAM = 'RESET.0\nMOVER.0 = 1000 : GO.0\nPAUSE IDLE.0\nPRINT "at ", POS.0, " with ", gain\n'
CONFIGURATION = "DIM gain = 7\n"


def shown_output(client: LanguageClient) -> str:
    """The text of the output document the server last asked the editor to show."""
    document = client.shown_documents[-1]
    assert not document.take_focus  # the user goes on editing the program
    return Path(to_fs_path(document.uri)).read_text(encoding="utf-8")


async def simulate(client: LanguageClient, uri: str) -> dict:
    return await client.workspace_execute_command_async(
        types.ExecuteCommandParams(command="mint.simulateFile", arguments=[uri])
    )


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
    assert "at 1000 with 7" in shown_output(client)
    assert client.messages[-1].message.startswith("Simulation end after")


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
    assert "at 1000 with 7" in shown_output(client)


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


@pytest.mark.asyncio
async def test_the_run_is_shown_as_progress_that_can_be_cancelled(client: LanguageClient, tmp_path: Path) -> None:
    program = tmp_path / "forever.mnt"
    program.write_text("DIM n = 0\nLOOP\n  n = n + 1\nENDL\n", encoding="utf-8")  # would run 20 s of wall time
    running = asyncio.ensure_future(simulate(client, uri_of(program)))
    while not any(client.progress_reports.values()):  # the run has begun
        await asyncio.sleep(0.05)
    [token] = client.progress_reports
    [begin, *_] = client.progress_reports[token]
    assert isinstance(begin, types.WorkDoneProgressBegin) and begin.cancellable
    client.window_work_done_progress_cancel(types.WorkDoneProgressCancelParams(token=token))
    report = await asyncio.wait_for(running, 15)  # a hang guard, not a timing
    assert report["stopped"] == "interrupted" and report["message"] == "cancelled by the user"
    assert isinstance(client.progress_reports[token][-1], types.WorkDoneProgressEnd)
    assert client.messages[-1].type == types.MessageType.Warning


@pytest.mark.asyncio
async def test_a_client_that_cannot_show_a_document_gets_the_output_in_the_message(
    neovim: LanguageClient, tmp_path: Path
) -> None:
    program = tmp_path / "count.mnt"
    program.write_text('DIM i\nFOR i = 1 TO 30\n  PRINT "line ", i\nNEXT\n', encoding="utf-8")
    report = await simulate(neovim, uri_of(program))
    assert report["stopped"] == "end"
    [message] = [m for m in neovim.messages if m.message.startswith("Simulation end")]
    lines = message.message.splitlines()
    assert lines[1:] == ["… (10 lines before)", *(f"line {i}" for i in range(11, 31))]
    assert neovim.shown_documents == []


@pytest.mark.asyncio
async def test_cancelling_the_command_request_stops_the_run(client: LanguageClient, tmp_path: Path) -> None:
    program = tmp_path / "forever.mnt"
    # each pass reads an input, so every tick is simulated whole: ten minutes take long enough to cancel
    program.write_text("DIM n = 0\nLOOP\n  n = n + IN0\nENDL\n", encoding="utf-8")
    params = types.ExecuteCommandParams(command="mint.simulateFile", arguments=[uri_of(program)])
    before = set(client.protocol._request_futures)
    answer = client.protocol.send_request(types.WORKSPACE_EXECUTE_COMMAND, params)
    [request_id] = [key for key, future in client.protocol._request_futures.items() if future is answer]
    assert request_id not in before
    while not any(client.progress_reports.values()):  # the run has begun
        await asyncio.sleep(0.05)
    client.protocol.notify(types.CANCEL_REQUEST, types.CancelParams(id=request_id))
    with pytest.raises(JsonRpcException, match="cancel"):
        await asyncio.wait_for(asyncio.wrap_future(answer), 15)  # a hang guard, not a timing
    [token] = client.progress_reports
    while not isinstance(client.progress_reports[token][-1], types.WorkDoneProgressEnd):
        await asyncio.sleep(0.05)
    assert client.progress_reports[token][-1].message == "cancelled by the user"
