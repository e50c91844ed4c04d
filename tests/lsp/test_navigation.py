"""Definition, references and highlights across the program and its configuration file."""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import corpus, document, open_document, position, uri_of

pytestmark = pytest.mark.asyncio
XY = corpus("ch01_l0144_xy_example.mnt")


async def test_definition_of_a_label_and_an_array(client, tmp_path):
    uri = uri_of(tmp_path / "xy.mnt")
    await open_document(client, uri, XY)
    [label] = await client.text_document_definition_async(
        types.DefinitionParams(text_document=document(uri), position=position(XY, "GOSUB main", 7))
    )
    assert label.range.start == types.Position(line=19, character=0)
    [array] = await client.text_document_definition_async(
        types.DefinitionParams(text_document=document(uri), position=position(XY, "ypos(a)"))
    )
    assert array.range.start == types.Position(line=7, character=4)


async def test_references_and_highlights(client, tmp_path):
    uri = uri_of(tmp_path / "xy.mnt")
    await open_document(client, uri, XY)
    where = position(XY, "GOSUB init", 7)
    context = types.ReferenceContext(include_declaration=True)
    found = await client.text_document_references_async(
        types.ReferenceParams(text_document=document(uri), position=where, context=context)
    )
    assert sorted(location.range.start.line for location in found) == [9, 13, 35]
    highlights = await client.text_document_document_highlight_async(
        types.DocumentHighlightParams(text_document=document(uri), position=position(XY, "FOR a", 4))
    )
    kinds = {h.range.start.line: h.kind for h in highlights}
    assert kinds[20] == types.DocumentHighlightKind.Write and kinds[27] == types.DocumentHighlightKind.Read


async def test_ten_significant_characters(client, tmp_path):
    text = "DIM position_x\nposition_xyz = 1\n"
    uri = uri_of(tmp_path / "identity.mnt")
    await open_document(client, uri, text)
    [found] = await client.text_document_definition_async(
        types.DefinitionParams(text_document=document(uri), position=position(text, "position_xyz"))
    )
    assert found.range.start == types.Position(line=0, character=4)


async def test_macro_defined_in_the_configuration_file(client, tmp_path):
    (tmp_path / "cell.cfg").write_text("REM axes\nDEFINE fast = 500\n", encoding="utf-8")
    text = "SPEED = fast\n"
    uri = uri_of(tmp_path / "cell.mnt")
    await open_document(client, uri, text)
    [found] = await client.text_document_definition_async(
        types.DefinitionParams(text_document=document(uri), position=position(text, "fast"))
    )
    assert found.uri == uri_of(tmp_path / "cell.cfg")
    assert found.range.start == types.Position(line=1, character=7)


async def test_keywords_have_no_definition(client, tmp_path):
    uri = uri_of(tmp_path / "xy.mnt")
    await open_document(client, uri, XY)
    found = await client.text_document_definition_async(
        types.DefinitionParams(text_document=document(uri), position=position(XY, "MOVEA"))
    )
    assert found is None


async def test_a_macro_use_is_the_macro_and_the_names_in_its_body_are_found(client, tmp_path):
    text = "DIM target = 10\nDEFINE fast = SPEED.0 = target\nfast\nPRINT target\n"
    uri = uri_of(tmp_path / "macro.mnt")
    await open_document(client, uri, text)
    [found] = await client.text_document_definition_async(
        types.DefinitionParams(text_document=document(uri), position=position(text, "fast\n"))
    )
    assert found.range.start == types.Position(line=1, character=7)  # the DEFINE, not the DIM of target
    [found] = await client.text_document_definition_async(
        types.DefinitionParams(text_document=document(uri), position=position(text, "= target", 3))
    )
    assert found.range.start == types.Position(line=0, character=4)
    context = types.ReferenceContext(include_declaration=True)
    found = await client.text_document_references_async(
        types.ReferenceParams(text_document=document(uri), position=position(text, "PRINT target", 7), context=context)
    )
    assert [(location.range.start.line, location.range.start.character) for location in found] == [
        (0, 4),
        (1, 24),
        (3, 6),
    ]
    highlights = await client.text_document_document_highlight_async(
        types.DocumentHighlightParams(text_document=document(uri), position=position(text, "DIM target", 4))
    )
    assert {(h.range.start.line, h.kind) for h in highlights} == {
        (0, types.DocumentHighlightKind.Write),
        (1, types.DocumentHighlightKind.Read),
        (3, types.DocumentHighlightKind.Read),
    }


async def test_a_label_definition_is_highlighted_as_written(client, tmp_path):
    uri = uri_of(tmp_path / "xy.mnt")
    await open_document(client, uri, XY)
    highlights = await client.text_document_document_highlight_async(
        types.DocumentHighlightParams(text_document=document(uri), position=position(XY, "GOSUB init", 7))
    )
    kinds = {h.range.start.line: h.kind for h in highlights}
    assert kinds[13] == types.DocumentHighlightKind.Write and kinds[9] == types.DocumentHighlightKind.Read


# The manual's macro that names another macro (3.5: "A macro cannot contain the reference to another
# macro. A syntax error will result at run time"), with a variable and a subroutine in macro texts.
MACROS = (
    "DIM speed0 = 5\nDEFINE myMacro = 1\nDEFINE myMove = MOVEA.myMacro = 100 : GO.myMacro\n"
    "DEFINE go0 = SPEED.0 = speed0 : GOSUB homing\nmyMove\ngo0\nEND\n#homing\nRETURN\n"
)


@pytest.mark.parametrize(
    ("needle", "shift", "defined"),
    [
        ("myMacro = 100", 2, (1, 7)),  # the macro, not the undeclared variable its expansion records
        ("myMacro\n", 0, (1, 7)),
        ("speed0 :", 3, (0, 4)),
        ("homing\nmyMove", 1, (7, 0)),
    ],
)
async def test_definition_inside_the_text_of_a_macro(client, tmp_path, needle, shift, defined):
    uri = uri_of(tmp_path / "macros.mnt")
    await open_document(client, uri, MACROS)
    where = position(MACROS, needle, shift)
    [found] = await client.text_document_definition_async(
        types.DefinitionParams(text_document=document(uri), position=where)
    )
    assert found.range.start == types.Position(*defined)
    renamed = await client.text_document_rename_async(
        types.RenameParams(text_document=document(uri), position=where, new_name="renamed")
    )
    edited = {(edit.range.start.line, edit.range.start.character) for edit in renamed.changes[uri]}
    assert (where.line, MACROS.splitlines()[where.line].index(needle.split()[0])) in edited  # the same token


async def test_highlights_of_a_label_and_its_jumps(client, tmp_path):
    uri = uri_of(tmp_path / "xy.mnt")
    await open_document(client, uri, XY)
    highlights = await client.text_document_document_highlight_async(
        types.DocumentHighlightParams(text_document=document(uri), position=position(XY, "GOSUB init", 7))
    )
    kinds = {h.range.start.line: h.kind for h in highlights}
    assert kinds == {
        13: types.DocumentHighlightKind.Write,  # the label
        9: types.DocumentHighlightKind.Read,
        35: types.DocumentHighlightKind.Read,
    }
