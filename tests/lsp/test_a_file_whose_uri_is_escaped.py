"""A program whose URI the client escapes is served as any other.

A folder or file name with a space or a letter outside ASCII is written escaped in a URI
(``Press%201``, ``%C3%A9``), and VS Code on Windows escapes the drive's colon in every one
(``file:///c%3A/...``). Such a program got no diagnostics, no hover, no definition, and completion
failed: the documents were looked up by the URI as sent, where the editor's copies are kept under
the unescaped one.
"""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import document, open_document, position, uri_of

pytestmark = pytest.mark.asyncio
PROGRAM = "DIM n = 0\nn = n + quota\nPRINT m\n"


@pytest.fixture
def escaped(tmp_path) -> str:
    folder = tmp_path / "Press 1"
    folder.mkdir()
    (folder / "café.cfg").write_text("DIM quota = 5\n", encoding="utf-8")
    uri = uri_of(folder / "café.mnt")
    assert "Press%201" in uri and "caf%C3%A9" in uri
    return uri


async def test_its_diagnostics_are_published_under_its_uri(client, escaped):
    diagnostics = await open_document(client, escaped, PROGRAM)
    assert [(d.code, d.range.start.line) for d in diagnostics] == [("E3001", 2)]  # m undeclared; quota is in café.cfg


async def test_hover_definition_completion_and_rename_answer(client, escaped):
    await open_document(client, escaped, PROGRAM)
    where = position(PROGRAM, "quota")
    hover = await client.text_document_hover_async(types.HoverParams(text_document=document(escaped), position=where))
    assert hover is not None and "quota" in hover.contents.value
    [found] = await client.text_document_definition_async(
        types.DefinitionParams(text_document=document(escaped), position=where)
    )
    assert found.uri == escaped.replace(".mnt", ".cfg")
    completion = await client.text_document_completion_async(
        types.CompletionParams(text_document=document(escaped), position=position(PROGRAM, "PRINT m", 6))
    )
    assert "n" in {item.label for item in completion.items}
    edit = await client.text_document_rename_async(
        types.RenameParams(text_document=document(escaped), position=where, new_name="most")
    )
    edited = set(edit.changes or {}) | {change.text_document.uri for change in edit.document_changes or []}
    assert edited == {escaped, escaped.replace(".mnt", ".cfg")}
