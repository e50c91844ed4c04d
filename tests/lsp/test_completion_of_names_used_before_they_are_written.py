"""What a program names before writing it is offered where it is written: a new program is typed top down, its
GOSUBs before their subroutines, its assignments before the DIM that should go above them.

After ``#`` at the start of a line (a label, 000:1843-1844), the labels a GOSUB or GOTO names that no line
defines yet come with the event handlers; after ``DIM``, the names used that no DIM declares (each is error
3001, 'Variable undefined, use DIM', 000:19073). A name already written is not offered again.
"""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import open_document, uri_of
from tests.lsp.test_completion import labels_at

pytestmark = pytest.mark.asyncio


async def test_a_hash_offers_the_labels_jumped_to_and_not_yet_written(client, tmp_path):
    text = "GOSUB init\nGOSUB main\nGOTO done\nEND\n#main\nRETURN\n#\n"
    uri = uri_of(tmp_path / "cell.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, "#\n", 1)
    assert {"#init", "#done", "#ONERROR"} <= set(items)
    assert "#main" not in items
    assert items["#init"].text_edit.new_text == "#init"


async def test_the_label_begun_is_offered_whole(client, tmp_path):
    text = "GOSUB homeAxes\nEND\n#ho\n"
    uri = uri_of(tmp_path / "cell.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, "#ho\n", 3)
    edit = items["#homeAxes"].text_edit
    assert (edit.range.start.line, edit.range.start.character, edit.range.end.character) == (2, 0, 3)


async def test_dim_offers_the_names_used_and_not_declared(client, tmp_path):
    text = "DIM \nDIM total\nLOOP\n  count = count + 1\n  total = total + rate\nENDL\n"
    uri = uri_of(tmp_path / "cell.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, "DIM \n", 4)
    assert set(items) == {"count", "rate"}


async def test_dim_in_a_v3_program_offers_no_name_in_use(client, tmp_path):
    # v3 variables need no DIM, which makes arrays (001:1525-1528): a name already used is no array to make
    client.workspace_did_change_configuration(types.DidChangeConfigurationParams(settings={"mint": {"dialect": "v3"}}))
    text = "DIM \nLOOP\n  count = count + 1\nENDL\n"
    uri = uri_of(tmp_path / "old.mnt")
    await open_document(client, uri, text)
    assert await labels_at(client, uri, text, "DIM \n", 4) == {}
