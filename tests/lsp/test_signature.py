"""Signature help shows the manual's formats and the operand under the cursor."""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import SHARED, document, open_document, position, uri_of

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


async def active(client, uri, text, needle, shift=0) -> tuple[str, str | None]:
    """The first signature's label and the text of its active parameter."""
    found = await help_at(client, uri, text, needle, shift)
    signature = found.signatures[0]
    if signature.parameters is None or found.active_parameter is None:
        return signature.label, None
    start, end = signature.parameters[found.active_parameter].label
    return signature.label, signature.label[start:end]


PRINT = "PRINT {#<terminal>} argument, {argument}, {modifier argument} {USING <int> {,<frac>}}"
INPUT = "INPUT {#<terminal>} {string,} variable {USING <int> {,<frac>}}"


@SHARED
@pytest.mark.parametrize(
    ("line", "label", "parameter"),
    [
        ("CAMTABLE(0, arr, ", "CAMTABLE ( axis, position array, {master increment array} )", "master increment array"),
        # its operands are all in its brackets (000:7907): none is left once they are closed
        ("CAMTABLE(0, arr, NULL)", "CAMTABLE ( axis, position array, {master increment array} )", None),
        ("COMMS(1, ", "COMMS( {node, } element) = <expression>", "element"),
        ("a = COMMS(1, ", "v = COMMS( {node, } element)", "element"),
        ("MOVEA.0 = 1, 2, ", "MOVEA[axes] = <expression> {,<expression ...}", "<expression ..."),
        ("CIRCLEA[0,1] = 1, 2, ", "CIRCLEA[axis0,axis1] = <centre0>,<centre1>,<angle>", "<angle>"),
        # In the brackets after the keyword the operands are its axes (000:8152), not the values after '='
        ("CIRCLEA[", "CIRCLEA[axis0,axis1] = <centre0>,<centre1>,<angle>", "axis0"),
        ("CIRCLEA[0, ", "CIRCLEA[axis0,axis1] = <centre0>,<centre1>,<angle>", "axis1"),
        ("MOVEA[0, 1, ", "MOVEA[axes] = <expression> {,<expression ...}", "axes"),
        ("PAUSE ", "PAUSE <condition>", "<condition>"),
        ("LOCATE #1, 5, ", "LOCATE {#<terminal>} <column>,<row>", "<row>"),
        # the guide writes the terminal with no comma after it (000:13693, 13660, 15307)
        ("LOCATE #3 10,", "LOCATE {#<terminal>} <column>,<row>", "<row>"),
        ("LINE #3 2, ", "LINE {#<terminal>} <line number>, <expression>", "<expression>"),
        ('PRINT #3 "Pos: ", a, ', PRINT, "modifier argument"),
        # as many values as the line holds (000:15305), LINE taking all PRINT's (000:13657-13660, 15353)
        ('PRINT "a = ",a," POS = ",', PRINT, "modifier argument"),
        ('LINE #3 2, "A = ", ', "LINE {#<terminal>} <line number>, <expression>", "<expression>"),
        ('LINE 2, "a"; a; ', "LINE {#<terminal>} <line number>, <expression>", "<expression>"),
        ("CAMEND[0,1] = 1, 2, ", "CAMEND[axes] = <expression> {,<expression>}", "<expression>"),
        # PRINT {#<terminal>} argument, {argument}, {modifier argument} {USING <int> {,<frac>}} (000:15295-15296):
        # values separated by commas or semicolons (000:15298-15299), the USING clause reached by its word.
        ("PRINT a, ", PRINT, "argument"),
        ('PRINT "x"; a, ', PRINT, "modifier argument"),
        ("PRINT #2, a, ", PRINT, "argument"),
        ("PRINT a USING ", PRINT, "<int>"),
        ("PRINT a, a USING 5, ", PRINT, "<frac>"),
        # INPUT {#<terminal>} {string,} variable {USING <int> {,<frac>}} (000:12212)
        ('INPUT "A = ", ', INPUT, "variable"),
        ('INPUT "A = ", a USING -5, ', INPUT, "<frac>"),
    ],
)
async def test_the_operand_under_the_cursor_is_highlighted_in_the_form_in_use(
    shared_client, tmp_path, line, label, parameter
):
    text = f"DIM a\nDIM arr(3)\n{line}\n"
    uri = uri_of(tmp_path / "operands.mnt")
    await open_document(shared_client, uri, text)
    assert await active(shared_client, uri, text, line, len(line)) == (label, parameter)
