"""Inlay hints: full names of abbreviated keywords and the values of macros."""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import document, open_document, uri_of

pytestmark = pytest.mark.asyncio


async def test_abbreviations_and_macros(client, tmp_path):
    text = "DEFINE fast = 100 * 2\nsp.0 = fast\nSPEED.1 = 10\nDIM a\na = IN3\n"
    uri = uri_of(tmp_path / "hints.mnt")
    await open_document(client, uri, text)
    whole = types.Range(start=types.Position(line=0, character=0), end=types.Position(line=5, character=0))
    hints = await client.text_document_inlay_hint_async(types.InlayHintParams(text_document=document(uri), range=whole))
    found = [((h.position.line, h.position.character), h.label) for h in hints]
    assert found == [((1, 2), "≡ SPEED"), ((1, 11), "≡ 100 * 2")]
    assert hints[0].tooltip == "sp is the abbreviation of SPEED"


async def test_macro_text_as_written_and_the_print_abbreviation(client, tmp_path):
    text = "DEFINE go0 = SPEED.0 = 500 : GO.0\ngo0\n? 1\n"
    uri = uri_of(tmp_path / "hints.mnt")
    await open_document(client, uri, text)
    whole = types.Range(start=types.Position(line=0, character=0), end=types.Position(line=3, character=0))
    hints = await client.text_document_inlay_hint_async(types.InlayHintParams(text_document=document(uri), range=whole))
    found = [((h.position.line, h.position.character), h.label) for h in hints]
    assert found == [((1, 3), "≡ SPEED.0 = 500 : GO.0"), ((2, 1), "≡ PRINT")]


async def test_a_macro_for_an_axis_reads_as_no_assignment(client, tmp_path):
    # the case: "SCALE[xAxis = 0, …]" looked like code; no Mint operator is ≡
    text = "DEFINE xAxis = 0\nDEFINE yAxis = 1\nSCALE[xAxis, yAxis] = 10;\n"
    uri = uri_of(tmp_path / "axes.mnt")
    await open_document(client, uri, text)
    whole = types.Range(start=types.Position(line=0, character=0), end=types.Position(line=3, character=0))
    hints = await client.text_document_inlay_hint_async(types.InlayHintParams(text_document=document(uri), range=whole))
    line = text.splitlines()[2]
    for hint in sorted(hints, key=lambda h: -h.position.character):
        line = f"{line[: hint.position.character]} {hint.label} {line[hint.position.character :]}"
    assert line == "SCALE[xAxis ≡ 0 , yAxis ≡ 1 ] = 10;"
    assert "=" not in "".join(hint.label for hint in hints)
    assert hints[0].tooltip == "macro xAxis: DEFINE xAxis = 0"
