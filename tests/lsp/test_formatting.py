"""Formatting: upper-case keywords and block indentation, nothing else touched."""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import document, open_document, uri_of

pytestmark = pytest.mark.asyncio
SPACES = types.FormattingOptions(tab_size=2, insert_spaces=True)


def apply(text: str, edits: list[types.TextEdit]) -> str:
    lines = text.split("\n")
    for edit in sorted(edits, key=lambda e: (e.range.start.line, e.range.start.character), reverse=True):
        start, end = edit.range.start, edit.range.end
        assert start.line == end.line
        line = lines[start.line]
        lines[start.line] = line[: start.character] + edit.new_text + line[end.character :]
    return "\n".join(lines)


SOURCE = """\
rem keep   THIS comment
dim i
#main
loop
for i = 1 to 10
if in1 do
print "if in1 do"  :  REM   spacing kept
   else
   out1=0
endif
next
endl
return
"""
FORMATTED = """\
REM keep   THIS comment
DIM i
#main
LOOP
  FOR i = 1 TO 10
    IF IN1 DO
      PRINT "if in1 do"  :  REM   spacing kept
    ELSE
      OUT1=0
    ENDIF
  NEXT
ENDL
RETURN
"""


async def test_whole_document(client, tmp_path):
    uri = uri_of(tmp_path / "messy.mnt")
    await open_document(client, uri, SOURCE)
    edits = await client.text_document_formatting_async(
        types.DocumentFormattingParams(text_document=document(uri), options=SPACES)
    )
    assert apply(SOURCE, edits) == FORMATTED


async def test_formatted_text_is_stable(client, tmp_path):
    uri = uri_of(tmp_path / "tidy.mnt")
    await open_document(client, uri, FORMATTED)
    edits = await client.text_document_formatting_async(
        types.DocumentFormattingParams(text_document=document(uri), options=SPACES)
    )
    assert not edits


async def test_a_document_with_a_syntax_error_is_left_as_it_is(client, tmp_path):
    # as mint format leaves it: what the compiler cannot read may be words meant as text, a C comment's
    # (Mint's comments begin with REM, 000:15506-15510), which upper case would change
    text = "// for the next part\nfor i = 1 to 2\nnext\n"
    uri = uri_of(tmp_path / "unreadable.mnt")
    await open_document(client, uri, text)
    whole = await client.text_document_formatting_async(
        types.DocumentFormattingParams(text_document=document(uri), options=SPACES)
    )
    selection = types.Range(start=types.Position(line=1, character=0), end=types.Position(line=2, character=0))
    part = await client.text_document_range_formatting_async(
        types.DocumentRangeFormattingParams(text_document=document(uri), range=selection, options=SPACES)
    )
    assert (list(whole or []), list(part or [])) == ([], [])


async def test_the_projects_format_table_wins_over_the_editors_indentation(client, tmp_path):
    # the editor writes what mint format --check accepts in CI: [format] indent-style = "tab" in mint.toml
    (tmp_path / "mint.toml").write_text('[format]\nindent-style = "tab"\n', encoding="utf-8")
    uri = uri_of(tmp_path / "project.mnt")
    text = "LOOP\nPRINT 1\nENDL\n"
    await open_document(client, uri, text)
    edits = await client.text_document_formatting_async(
        types.DocumentFormattingParams(text_document=document(uri), options=SPACES)
    )
    assert apply(text, edits) == "LOOP\n\tPRINT 1\nENDL\n"


async def test_range_formats_only_those_lines(client, tmp_path):
    uri = uri_of(tmp_path / "part.mnt")
    await open_document(client, uri, SOURCE)
    selection = types.Range(start=types.Position(line=4, character=0), end=types.Position(line=4, character=3))
    edits = await client.text_document_range_formatting_async(
        types.DocumentRangeFormattingParams(text_document=document(uri), range=selection, options=SPACES)
    )
    assert {e.range.start.line for e in edits} == {4}
    assert apply(SOURCE, edits).split("\n")[4] == "  FOR i = 1 TO 10"


async def test_a_selection_of_whole_lines_ends_before_the_next_line(client, tmp_path):
    uri = uri_of(tmp_path / "lines.mnt")
    await open_document(client, uri, SOURCE)
    selection = types.Range(start=types.Position(line=4, character=0), end=types.Position(line=5, character=0))
    edits = await client.text_document_range_formatting_async(
        types.DocumentRangeFormattingParams(text_document=document(uri), range=selection, options=SPACES)
    )
    assert {e.range.start.line for e in edits} == {4}


async def test_a_range_running_past_the_end_formats_up_to_the_end(client, tmp_path):
    # some clients send "the whole file" as a range past its last line; the last line has no line end here
    text = "DIM a\nloop\n  a = 1\nendl"
    uri = uri_of(tmp_path / "open_end.mnt")
    await open_document(client, uri, text)
    for start, end in ((0, 99), (5, 8)):
        beyond = types.Position(line=end, character=9)
        selection = types.Range(start=types.Position(line=start, character=0), end=beyond)
        edits = await client.text_document_range_formatting_async(
            types.DocumentRangeFormattingParams(text_document=document(uri), range=selection, options=SPACES)
        )
        assert apply(text, edits) == (text.replace("loop", "LOOP").replace("endl", "ENDL") if start == 0 else text)


async def test_keywords_in_the_text_of_a_macro_are_upper_cased_too(client, tmp_path):
    text = 'define m = print 1 : print "a"\n'
    uri = uri_of(tmp_path / "macro.mnt")
    await open_document(client, uri, text)
    edits = await client.text_document_formatting_async(
        types.DocumentFormattingParams(text_document=document(uri), options=SPACES)
    )
    assert apply(text, edits) == 'DEFINE m = PRINT 1 : PRINT "a"\n'


async def test_an_indented_label_goes_to_the_margin_with_its_body_and_trailing_blanks_go(client, tmp_path):
    # the case: the body went to column 0 and its label stayed indented, trailing spaces kept
    text = "DIM a \nGOSUB init\nEND\n  #init  \n  a = 10\t\n  loop : a = 1\n   \n  endl\n  return   \n"
    uri = uri_of(tmp_path / "labels.mnt")
    await open_document(client, uri, text)
    edits = await client.text_document_formatting_async(
        types.DocumentFormattingParams(text_document=document(uri), options=SPACES)
    )
    assert apply(text, edits) == "DIM a\nGOSUB init\nEND\n#init\na = 10\nLOOP : a = 1\n\nENDL\nRETURN\n"
    assert all(edit.range.start.line == edit.range.end.line for edit in edits)  # one edit per changed line


async def test_a_label_named_like_a_keyword_keeps_its_case(client, tmp_path):
    # a label is any alphanumeric name (000:1843): after GOSUB and GOTO, home and sin name labels, not HOME and SIN
    text = "gosub home : goto sin\n#sin\nend\n#home\nreturn\n"
    uri = uri_of(tmp_path / "named.mnt")
    await open_document(client, uri, text)
    edits = await client.text_document_formatting_async(
        types.DocumentFormattingParams(text_document=document(uri), options=SPACES)
    )
    assert apply(text, edits) == "GOSUB home : GOTO sin\n#sin\nEND\n#home\nRETURN\n"
