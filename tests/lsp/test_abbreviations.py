"""Expanding abbreviated keywords, a refactoring at the cursor or over a selection."""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import document, open_document, uri_of

pytestmark = pytest.mark.asyncio
# Abbreviations as the guide writes them (SF.g1 of 3.5, HS for HOMESPEED), "?" for PRINT, and a full
# name and a glued channel that are no abbreviation.
TEXT = "DIM a\nSF.0 = 10 : sp.1 = 20\nHS = 5\na = IN3\n? a : SPEED = 1\n"


async def rewrites(client, uri, start, end) -> list[types.CodeAction]:
    selection = types.Range(start=types.Position(*start), end=types.Position(*end))
    context = types.CodeActionContext(diagnostics=[], only=[types.CodeActionKind.Refactor])
    return await client.text_document_code_action_async(
        types.CodeActionParams(text_document=document(uri), range=selection, context=context)
    )


def applied(text: str, action: types.CodeAction, uri: str) -> str:
    lines = text.split("\n")
    for edit in sorted(action.edit.changes[uri], key=lambda e: e.range.start, reverse=True):
        line = lines[edit.range.start.line]
        lines[edit.range.start.line] = (
            line[: edit.range.start.character] + edit.new_text + line[edit.range.end.character :]
        )
    return "\n".join(lines)


async def test_the_abbreviation_at_the_cursor(client, tmp_path):
    uri = uri_of(tmp_path / "short.mnt")
    await open_document(client, uri, TEXT)
    [action] = await rewrites(client, uri, (1, 13), (1, 13))  # in "sp"
    assert (action.title, action.kind) == ("Expand sp to SPEED", types.CodeActionKind.RefactorRewrite)
    assert applied(TEXT, action, uri).split("\n")[1] == "SF.0 = 10 : SPEED.1 = 20"


async def test_every_abbreviation_of_a_selection(client, tmp_path):
    uri = uri_of(tmp_path / "short.mnt")
    await open_document(client, uri, TEXT)
    [action] = await rewrites(client, uri, (0, 0), (5, 0))
    assert action.title == "Expand 4 abbreviations"
    assert (
        applied(TEXT, action, uri)
        == "DIM a\nSCALE.0 = 10 : SPEED.1 = 20\nHOMESPEED = 5\na = IN3\nPRINT a : SPEED = 1\n"
    )


async def test_nothing_to_expand_offers_nothing(client, tmp_path):
    uri = uri_of(tmp_path / "short.mnt")
    await open_document(client, uri, TEXT)
    assert not await rewrites(client, uri, (3, 0), (3, 7))  # "a = IN3"


@pytest.mark.parametrize(
    ("line", "expanded"),
    [
        pytest.param("?FASTPOS.2;FASTPOS.3", "PRINT FASTPOS.2;FASTPOS.3", id="glued-to-the-keyword-it-prints"),
        pytest.param("?a", "PRINT a", id="glued-to-a-variable"),
        pytest.param('?"x"', 'PRINT"x"', id="before-a-string-nothing-to-part"),
        pytest.param("IF a THEN?a", "IF a THEN PRINT a", id="glued-on-both-sides"),
    ],
)
async def test_a_question_mark_glued_to_a_word_expands_to_print_and_a_space(client, tmp_path, line, expanded):
    """PRINT may be written ``?`` (000:15302), glued to what it prints (``?FASTPOS.2``, 000:10452); written out
    in full, ``PRINTFASTPOS`` would be one name, not the keyword and its argument."""
    text = f"DIM a\n{line}\n"
    uri = uri_of(tmp_path / "short.mnt")
    await open_document(client, uri, text)
    [action] = await rewrites(client, uri, (1, 0), (2, 0))
    assert action.title == "Expand ? to PRINT"
    assert applied(text, action, uri) == f"DIM a\n{expanded}\n"
