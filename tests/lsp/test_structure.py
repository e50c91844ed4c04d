"""Outline, workspace symbols, folding ranges and semantic tokens."""

from __future__ import annotations

import pytest
from lsprotocol import types

from mintlang.lsp.features.semantic_tokens import TOKEN_MODIFIERS, TOKEN_TYPES
from tests.lsp.conftest import corpus, document, open_document, uri_of

pytestmark = pytest.mark.asyncio
XY = corpus("ch01_l0144_xy_example.mnt")


async def test_outline(client, tmp_path):
    text = XY + "#ONERROR\nRETURN\nDEFINE fast = 10\n"
    uri = uri_of(tmp_path / "xy.mnt")
    await open_document(client, uri, text)
    symbols = await client.text_document_document_symbol_async(types.DocumentSymbolParams(text_document=document(uri)))
    outline = [(s.name, s.kind) for s in symbols]
    assert outline == [
        ("xpos", types.SymbolKind.Array),
        ("ypos", types.SymbolKind.Array),
        ("#init", types.SymbolKind.Function),
        ("#main", types.SymbolKind.Function),
        ("a", types.SymbolKind.Variable),
        ("#ONERROR", types.SymbolKind.Event),
        ("fast", types.SymbolKind.Constant),
    ]
    init = symbols[2]
    assert (init.range.start.line, init.range.end.line) == (13, 18)


async def test_outline_and_folding_of_a_program_without_subroutines(client, tmp_path):
    uri = uri_of(tmp_path / "flat.mnt")
    await open_document(client, uri, "DIM a\nFOR a = 1 TO 3\n  PRINT a\nNEXT\n")
    symbols = await client.text_document_document_symbol_async(types.DocumentSymbolParams(text_document=document(uri)))
    assert [(s.name, s.kind) for s in symbols] == [("a", types.SymbolKind.Variable)]
    ranges = await client.text_document_folding_range_async(types.FoldingRangeParams(text_document=document(uri)))
    assert [(r.start_line, r.end_line) for r in ranges] == [(1, 2)]


async def test_a_section_ends_before_the_comment_that_introduces_the_next(client, tmp_path):
    text = "GOSUB init\nEND\n#init\n  SPEED.0 = 10\nRETURN\n\nREM helpers below\n#onerror\nRETURN\n"
    uri = uri_of(tmp_path / "sections.mnt")
    await open_document(client, uri, text)
    ranges = await client.text_document_folding_range_async(types.FoldingRangeParams(text_document=document(uri)))
    assert (2, 4) in {(r.start_line, r.end_line) for r in ranges}
    symbols = await client.text_document_document_symbol_async(types.DocumentSymbolParams(text_document=document(uri)))
    init = next(symbol for symbol in symbols if symbol.name == "#init")
    assert init.range.end == types.Position(line=5, character=0)


async def test_workspace_symbols_span_open_documents(client, tmp_path):
    await open_document(client, uri_of(tmp_path / "xy.mnt"), XY)
    await open_document(client, uri_of(tmp_path / "menu.mnt"), corpus("ch03_l0815_main_menu_inkey.mnt"))
    found = await client.workspace_symbol_async(types.WorkspaceSymbolParams(query="ma"))
    assert {(s.name, s.location.uri.rsplit("/", 1)[1]) for s in found} >= {
        ("#main", "xy.mnt"),
        ("#mainMenu", "menu.mnt"),
    }


async def test_workspace_symbols_name_labels_as_the_outline_does(client, tmp_path):
    # a GOSUB's label is a subroutine, an event handler's an event (000:1878-1880), and a label only a GOTO names is
    # a place to jump to, not a routine
    text = "GOSUB setUp\nGOTO again\n#again\nPRINT 1\nEND\n#setUp\nRETURN\n#ONERROR\nRETURN\n"
    await open_document(client, uri_of(tmp_path / "kinds.mnt"), text)
    found = await client.workspace_symbol_async(types.WorkspaceSymbolParams(query=""))
    kinds = {s.name: s.kind for s in found if s.location.uri.endswith("kinds.mnt")}
    assert kinds == {
        "#setUp": types.SymbolKind.Function,
        "#again": types.SymbolKind.Key,
        "#ONERROR": types.SymbolKind.Event,
    }


async def test_folding_blocks_and_subroutines(client, tmp_path):
    text = "IF IN1 DO\n  OUT1 = 1\nELSE\n  OUT1 = 0\nENDIF\n" + XY
    uri = uri_of(tmp_path / "fold.mnt")
    await open_document(client, uri, text)
    ranges = await client.text_document_folding_range_async(types.FoldingRangeParams(text_document=document(uri)))
    spans = {(r.start_line, r.end_line) for r in ranges}
    assert {(0, 1), (2, 3)} <= spans  # the IF's two branches
    assert {(28, 42), (30, 38)} <= spans  # LOOP .. ENDL, FOR .. NEXT of the XY example (shifted 5 lines)
    assert (18, 22) in spans  # #init


async def test_the_last_subroutine_folds_to_its_last_line_not_past_the_final_line_break(client, tmp_path):
    text = "GOSUB init\nEND\n#init\nPRINT 1\nRETURN\n"  # LSP lines 0 to 5, the last one empty
    uri = uri_of(tmp_path / "last.mnt")
    await open_document(client, uri, text)
    ranges = await client.text_document_folding_range_async(types.FoldingRangeParams(text_document=document(uri)))
    assert [(r.start_line, r.end_line) for r in ranges] == [(2, 4)]


async def test_runs_of_comment_lines_fold_as_comments(client, tmp_path):
    # the manual's program file opens with four REM lines (000:279-282); a lone comment line does not fold
    text = "REM Program file\nREM Project ..\nREM Author ...\nREM Date .....\n\nDIM a\nREM one line\na = 1\n"
    uri = uri_of(tmp_path / "remarks.mnt")
    await open_document(client, uri, text)
    ranges = await client.text_document_folding_range_async(types.FoldingRangeParams(text_document=document(uri)))
    assert [(r.start_line, r.end_line, r.kind) for r in ranges] == [(0, 3, types.FoldingRangeKind.Comment)]


async def coloured(client, uri: str, text: str) -> list[tuple[int, str, str, int]]:
    """The server's semantic tokens of ``text``, decoded: line, word, type and modifier bits."""
    tokens = await client.text_document_semantic_tokens_full_async(
        types.SemanticTokensParams(text_document=document(uri))
    )
    data, line, column, decoded = list(tokens.data), 0, 0, []
    for index in range(0, len(data), 5):
        delta_line, delta_start, length, kind, modifiers = data[index : index + 5]
        line += delta_line
        column = delta_start if delta_line else column + delta_start
        decoded.append((line, text.splitlines()[line][column : column + length], TOKEN_TYPES[kind], modifiers))
    return decoded


async def test_semantic_tokens(client, tmp_path):
    text = 'DEFINE fast = 10\nDIM a\na = fast + _TRUE : REM note\nPRINT "x"\n'
    uri = uri_of(tmp_path / "colour.mnt")
    await open_document(client, uri, text)
    decoded = [(word, kind) for _, word, kind, _ in await coloured(client, uri, text)]
    assert ("DEFINE", "keyword") in decoded
    assert decoded.count(("fast", "macro")) == 2
    assert ("a", "variable") in decoded
    assert ("_TRUE", "enumMember") in decoded
    assert ("REM note", "comment") in decoded
    assert ('"x"', "string") in decoded


async def test_a_label_named_like_a_keyword_or_a_variable_is_coloured_as_a_label(client, tmp_path):
    # after GOSUB and GOTO comes a label, which may take any alphanumeric name (000:1843)
    text = "DIM total\nGOSUB home : GOTO total\n#total\nEND\n#home\nRETURN\n"
    uri = uri_of(tmp_path / "labels.mnt")
    await open_document(client, uri, text)
    decoded = [(line, word, kind) for line, word, kind, _ in await coloured(client, uri, text)]
    assert [(word, kind) for at, word, kind in decoded if at == 1] == [
        ("GOSUB", "keyword"),
        ("home", "function"),
        ("GOTO", "keyword"),
        ("total", "function"),
    ]
    assert (0, "total", "variable") in decoded


async def test_a_v3_word_in_v4_code_is_a_deprecated_keyword_unless_declared(client, tmp_path):
    # the case: HMSPEED, the v3 name of HOMESPEED, is no variable of the program
    text = "DEFINE xAxis = 0\nDEFINE zAxis = 2\nHMSPEED[xAxis, zAxis] = 20, 10\nDIM gain\ngain = 2\n"
    uri = uri_of(tmp_path / "v3.mnt")
    await open_document(client, uri, text)
    decoded = {word: (kind, modifiers) for _, word, kind, modifiers in await coloured(client, uri, text)}
    assert decoded["HMSPEED"] == ("keyword", 1 << TOKEN_MODIFIERS.index("deprecated"))
    assert decoded["gain"] == ("variable", 0)  # GAIN was v3's KPROP, but the DIM makes it the user's


async def test_semantic_tokens_of_a_range_are_those_of_its_lines(client, tmp_path):
    text = "DIM a\na = 1\nPRINT a\n"
    uri = uri_of(tmp_path / "range.mnt")
    await open_document(client, uri, text)
    visible = types.Range(start=types.Position(line=1, character=0), end=types.Position(line=2, character=0))
    tokens = await client.text_document_semantic_tokens_range_async(
        types.SemanticTokensRangeParams(text_document=document(uri), range=visible)
    )
    data = list(tokens.data)
    first_line = data[0]  # relative to the start of the document: the range starts on line 1
    kinds = [TOKEN_TYPES[data[index + 3]] for index in range(0, len(data), 5)]
    assert (first_line, kinds) == (1, ["variable", "number"])  # "a = 1" only


async def test_the_outline_lists_a_files_own_declaration_when_the_other_file_has_one_too(client, tmp_path):
    (tmp_path / "cell.cfg").write_text("DIM shared\n", encoding="utf-8")
    uri = uri_of(tmp_path / "cell.mnt")
    await open_document(client, uri, "DIM shared\nDIM own\n")
    symbols = await client.text_document_document_symbol_async(types.DocumentSymbolParams(text_document=document(uri)))
    assert [s.name for s in symbols] == ["shared", "own"]
