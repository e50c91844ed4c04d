"""Go to declaration: the DIM, DEFINE or label that creates a name, first in compile order."""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import document, open_document, position, uri_of

pytestmark = pytest.mark.asyncio


async def declared(client, uri, text, needle, shift=0) -> list[types.Location] | None:
    return await client.text_document_declaration_async(
        types.DeclarationParams(text_document=document(uri), position=position(text, needle, shift))
    )


async def test_the_configuration_files_dim_declares_a_name_both_files_dim(client, tmp_path):
    # the configuration file is compiled first (the guide's RELEASE advice assumes its variables exist)
    configuration = tmp_path / "cell.cfg"
    configuration.write_text("DIM shared = 1\n", encoding="utf-8")
    text = "DIM shared\nshared = 2\n"
    uri = uri_of(tmp_path / "cell.mnt")
    await open_document(client, uri, text)
    [found] = await declared(client, uri, text, "shared = 2")
    assert (found.uri, found.range.start) == (uri_of(configuration), types.Position(line=0, character=4))
    definitions = await client.text_document_definition_async(
        types.DefinitionParams(text_document=document(uri), position=position(text, "shared = 2"))
    )
    assert len(definitions) == 2  # definition lists both DIMs


async def test_labels_and_macros(client, tmp_path):
    text = "DEFINE fast = 100\nGOSUB init\nEND\n#init\nSPEED = fast\nRETURN\n"
    uri = uri_of(tmp_path / "program.mnt")
    await open_document(client, uri, text)
    [label] = await declared(client, uri, text, "GOSUB init", 7)
    assert label.range.start == types.Position(line=3, character=0)
    [macro] = await declared(client, uri, text, "= fast", 3)
    assert macro.range.start == types.Position(line=0, character=7)
    assert await declared(client, uri, text, "SPEED") is None
