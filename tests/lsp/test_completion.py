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
    assert {"#ONERROR", "#STOP", "#TIMER", "#IN0", "#FASTIN0", "#COMMS1"} <= set(items)
    typed = items["#ONERROR"].text_edit  # replaces the "#" typed, whatever the client takes for a word
    assert (typed.new_text, typed.range.start.character, typed.range.end.character) == ("#ONERROR", 0, 1)


async def test_a_terminal_number_after_print_hash_gets_no_handler_names(client, tmp_path):
    text = "PRINT #\n"
    uri = uri_of(tmp_path / "terminal.mnt")
    await open_document(client, uri, text)
    assert await labels_at(client, uri, text, "#", 1) == {}


async def test_statement_start_offers_no_functions_operators_or_continuations(client, tmp_path):
    text = "DIM a\n\n"
    uri = uri_of(tmp_path / "start.mnt")
    await open_document(client, uri, text)
    items = set(await labels_at(client, uri, text, "a\n", 2))
    assert {"GO", "PRINT", "ELSE", "a"} <= items
    assert not items & {"SIN", "ABS", "AND", "NOT", "~", "THEN", "TO", "STEP", "USING", "DO", "#", ":"}


@pytest.mark.parametrize(
    ("line", "reason"),
    [
        ("DIM ", "a new name is declared"),
        ("DEFINE ", "a new name is defined"),
        ("SPEED.", "an axis number follows the dot"),
        ("a = 1.", "decimals follow"),
        ("a = 'b", "inside a character constant"),
    ],
)
async def test_nothing_where_no_word_of_the_list_can_go(client, tmp_path, line, reason):
    text = f"DIM a\n{line}\n"
    uri = uri_of(tmp_path / "nothing.mnt")
    await open_document(client, uri, text)
    assert await labels_at(client, uri, text, line, len(line)) == {}, reason


async def test_after_an_operand_the_operators_and_continuations(client, tmp_path):
    text = "DIM a\nIF a \n"
    uri = uri_of(tmp_path / "operand.mnt")
    await open_document(client, uri, text)
    items = set(await labels_at(client, uri, text, "IF a ", 5))
    assert {"AND", "OR", "XOR", "MOD", "THEN", "DO"} <= items
    assert not items & {"POS", "SIN", "a"}


async def test_symbol_details_are_plain_text_and_the_description_is_markdown(client, tmp_path):
    text = "DIM a\nDEFINE fast = SPEED.0 = 500\na = \n"
    uri = uri_of(tmp_path / "details.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, "a = ", 4)
    assert (items["a"].detail, items["fast"].detail) == ("variable", "macro")
    assert "DEFINE fast = SPEED.0 = 500" in items["fast"].documentation.value  # as written, not re-spaced


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


@pytest.mark.parametrize("line", ["RETURN ", "END ", "ENDIF ", "NEXT ", "GO ", "SPEED ", "DIM _"])
async def test_nothing_after_a_complete_statement_or_a_command_awaiting_its_axes(client, tmp_path, line):
    text = f"DIM a\n{line}\n"
    uri = uri_of(tmp_path / "complete.mnt")
    await open_document(client, uri, text)
    assert await labels_at(client, uri, text, line, len(line)) == {}


async def test_a_keyword_read_is_an_operand_and_binary_operators_wait_for_one(client, tmp_path):
    text = "DIM a\nIF IN3 \na = \n"
    uri = uri_of(tmp_path / "operands.mnt")
    await open_document(client, uri, text)
    after = set(await labels_at(client, uri, text, "IF IN3 ", 7))
    assert {"AND", "OR", "THEN", "DO"} <= after and not after & {"NOT", "POS", "a"}
    before = set(await labels_at(client, uri, text, "a = ", 4))
    assert {"NOT", "POS", "a"} <= before and not before & {"AND", "OR", "MOD", "XOR"}
