"""Completion offers only what is valid where the cursor is."""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import change, corpus, document, open_document, position, uri_of

pytestmark = pytest.mark.asyncio


async def labels_at(client, uri, text, needle, shift=0) -> dict[str, types.CompletionItem]:
    found = await client.text_document_completion_async(
        types.CompletionParams(text_document=document(uri), position=position(text, needle, shift))
    )
    return {item.label: item for item in found.items}


async def test_statement_start_offers_commands_variables_and_snippets(client, tmp_path):
    text = corpus("ch01_l0144_xy_example.mnt") + "DEFINE fast = 10\n\n"
    uri = uri_of(tmp_path / "xy.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, "fast = 10\n", 10)
    assert {"GO", "SPEED", "MOVEA", "xpos", "a", "fast", "FOR … NEXT", "IF … DO … ENDIF"} <= set(items)
    assert items["SPEED"].detail == "parameter, abbreviation SP"
    assert items["FOR … NEXT"].insert_text_format == types.InsertTextFormat.Snippet
    assert "_TRUE" not in items and "init" not in items


async def test_expression_offers_readable_words_only(client, tmp_path):
    text = "DIM a\nDIM b\na = \n"
    uri = uri_of(tmp_path / "expression.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, "a = ", 4)
    assert {"POS", "SIN", "INKEY", "a", "b"} <= set(items)
    assert "GO" not in items and "FOR … NEXT" not in items  # commands and blocks are statements


async def test_labels_after_gosub(client, tmp_path):
    text = corpus("ch03_l0815_main_menu_inkey.mnt") + "GOSUB \n"
    uri = uri_of(tmp_path / "menu.mnt")
    await open_document(client, uri, text)
    assert set(await labels_at(client, uri, text, "GOSUB \n", 6)) == {"mainMenu", "start", "setup"}


async def test_constants_after_underscore(client, tmp_path):
    text = "DIM a\na = _\n"
    uri = uri_of(tmp_path / "constants.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, "_\n", 1)
    assert {"_TRUE", "_FALSE", "_hmPOSITIVE_SWITCH"} <= set(items)
    assert "SPEED" not in items


async def test_event_handlers_after_hash_at_line_start(client, tmp_path):
    text = "END\n#\n"
    uri = uri_of(tmp_path / "events.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, "#", 1)
    assert {"ONERROR", "STOP", "TIMER", "IN0", "FASTIN0", "COMMS1"} <= set(items)


async def test_nothing_inside_comments_and_strings(client, tmp_path):
    text = 'REM speed \nPRINT "spe"\n'
    uri = uri_of(tmp_path / "quiet.mnt")
    await open_document(client, uri, text)
    assert await labels_at(client, uri, text, "speed", 3) == {}
    assert await labels_at(client, uri, text, 'spe"', 2) == {}


async def test_resolve_adds_the_manual_entry(client, tmp_path):
    text = "\n"
    uri = uri_of(tmp_path / "resolve.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, "\n")
    resolved = await client.completion_item_resolve_async(items["HOMESPEED"])
    assert "**HOMESPEED**" in resolved.documentation.value


async def test_completion_while_typing_uses_the_line_as_typed(client, tmp_path):
    text = corpus("ch03_l0815_main_menu_inkey.mnt")
    uri = uri_of(tmp_path / "typing.mnt")
    await open_document(client, uri, text)
    end = len(text.splitlines())
    change(client, uri, 2, ((end, 0), (end, 0)), "GOSUB s")
    found = await client.text_document_completion_async(
        types.CompletionParams(text_document=document(uri), position=types.Position(line=end, character=7))
    )
    assert {item.label for item in found.items} == {"mainMenu", "start", "setup"}
