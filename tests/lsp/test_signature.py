"""Signature help shows the manual's formats and the operand under the cursor."""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import document, open_document, position, uri_of

pytestmark = pytest.mark.asyncio


async def help_at(client, uri, text, needle, shift=0) -> types.SignatureHelp | None:
    return await client.text_document_signature_help_async(
        types.SignatureHelpParams(text_document=document(uri), position=position(text, needle, shift))
    )


async def test_function_arguments(client, tmp_path):
    text = "DIM a\na = POW(2, 3)\n"
    uri = uri_of(tmp_path / "pow.mnt")
    await open_document(client, uri, text)
    found = await help_at(client, uri, text, "3)")
    assert found.signatures[0].label == "v = POW(x, y)"
    assert found.active_parameter == 1


async def test_keyword_write_values(client, tmp_path):
    text = "SPEED[0,1] = 10, 20\n"
    uri = uri_of(tmp_path / "speed.mnt")
    await open_document(client, uri, text)
    found = await help_at(client, uri, text, "20")
    assert "SPEED[axes] = <expression> {,<expression> ...}" in [s.label for s in found.signatures]
    assert found.active_parameter == 1


async def test_nothing_outside_keywords(client, tmp_path):
    text = "DIM a\na = 1\n"
    uri = uri_of(tmp_path / "plain.mnt")
    await open_document(client, uri, text)
    assert await help_at(client, uri, text, "1\n") is None
