"""The checker's fixes as the editor offers them: quick fixes on the diagnostics of the lines selected."""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import document, open_document, uri_of

pytestmark = pytest.mark.asyncio


async def fixes(client, uri, diagnostics, line) -> dict[str, types.CodeAction]:
    where = types.Range(start=types.Position(line=line, character=0), end=types.Position(line=line, character=80))
    context = types.CodeActionContext(diagnostics=diagnostics, only=[types.CodeActionKind.QuickFix])
    found = await client.text_document_code_action_async(
        types.CodeActionParams(text_document=document(uri), range=where, context=context)
    )
    return {action.title: action for action in found}


def applied(text: str, action: types.CodeAction, uri: str) -> str:
    """``text`` after the action's edits (insertions and deletions of whole lines included)."""
    starts = [0, *(index + 1 for index, character in enumerate(text) if character == "\n")]
    for edit in sorted(action.edit.changes[uri], key=lambda e: e.range.start, reverse=True):
        start = starts[edit.range.start.line] + edit.range.start.character
        end = (
            starts[edit.range.end.line] if edit.range.end.line < len(starts) else len(text)
        ) + edit.range.end.character
        text = text[:start] + edit.new_text + text[end:]
    return text


async def test_the_dim_goes_with_the_other_dims_not_into_the_loop(client, tmp_path):
    # the case: the DIM went inside the loop where the name is used
    text = "REM counter\nDIM most = 10\nLOOP\n  count = count + 1\n  IF count > most THEN EXIT\nENDL\n"
    uri = uri_of(tmp_path / "dim.mnt")
    diagnostics = await open_document(client, uri, text)
    found = await fixes(client, uri, diagnostics, 3)
    assert applied(text, found["Declare 'count' with DIM"], uri) == (
        "REM counter\nDIM most = 10\nDIM count\nLOOP\n  count = count + 1\n  IF count > most THEN EXIT\nENDL\n"
    )


async def test_in_a_file_of_event_handlers_alone_the_dim_opens_the_program_above_the_first_handler(client, tmp_path):
    """Mint v4 declares at compile time, in compile order (000:305-306, 000:957-972: a DIM in a subroutine never
    called still declares): a DIM needs no run, only to come before every use. Above the first handler is
    the start of the program, where the guide's layout puts its declarations (000:284-291); inside the
    handler it would declare only for the lines after it, and after END or at the file's end too late."""
    text = "REM input events\n#IN0\n  count = count + 1\nRETURN\n\n#IN1\n  PRINT count\nRETURN\n"
    uri = uri_of(tmp_path / "events.mnt")
    diagnostics = await open_document(client, uri, text)
    found = await fixes(client, uri, diagnostics, 6)  # from the second handler's use
    fixed = applied(text, found["Declare 'count' with DIM"], uri)
    assert fixed == "REM input events\nDIM count\n#IN0\n  count = count + 1\nRETURN\n\n#IN1\n  PRINT count\nRETURN\n"
    after = await open_document(client, uri_of(tmp_path / "fixed.mnt"), fixed)
    assert "E3001" not in {str(diagnostic.code) for diagnostic in after}


async def test_an_undeclared_array_is_declared_with_as_many_elements_as_its_largest_index(client, tmp_path):
    # the guide's array example (3.3, 000:1068-1075) without its DIM: my_var(10) needs DIM my_var(10)
    text = "REM arrays\nmy_var(10) = 100.5\nPRINT my_var(10)\n"
    uri = uri_of(tmp_path / "array.mnt")
    diagnostics = await open_document(client, uri, text)
    found = await fixes(client, uri, diagnostics, 1)
    assert "Declare 'my_var' with DIM" not in found  # DIM my_var makes a variable, which takes no index (2016)
    assert applied(text, found["Declare 'my_var(10)' with DIM"], uri) == (
        "REM arrays\nDIM my_var(10)\nmy_var(10) = 100.5\nPRINT my_var(10)\n"
    )


async def test_an_array_also_indexed_by_a_computed_index_is_left_for_its_author_to_size(client, tmp_path):
    # DIM vals(3) would hold vals(1) to vals(3) only (000:1068-1075): the loop's vals(4) would stop the run with
    # 2016, Invalid index; so no size is guessed, as when no index is a number
    text = "FOR i = 1 TO 5\n  vals(i) = i * 10\nNEXT\nPRINT vals(3)\n"
    uri = uri_of(tmp_path / "loop.mnt")
    diagnostics = await open_document(client, uri, text)
    for line in (1, 3):
        offered = await fixes(client, uri, diagnostics, line)
        assert not [title for title in offered if title.startswith("Declare 'vals")]


async def test_a_fix_shared_by_several_diagnostics_is_offered_once(client, tmp_path):
    # box is undeclared on three lines: one DIM declares it for all three
    text = "FOR box = 1 TO 4\n  MOVEA.0 = box * 250\n  PRINT box\nNEXT\n"
    uri = uri_of(tmp_path / "box.mnt")
    diagnostics = await open_document(client, uri, text)
    everything = types.Range(start=types.Position(line=0, character=0), end=types.Position(line=4, character=0))
    context = types.CodeActionContext(diagnostics=diagnostics, only=[types.CodeActionKind.QuickFix])
    found = await client.text_document_code_action_async(
        types.CodeActionParams(text_document=document(uri), range=everything, context=context)
    )
    titles = [action.title for action in found]
    assert titles.count("Declare 'box' with DIM") == 1
    ignores = ["Ignore E3001 on line 1", "Ignore E3001 on line 2", "Ignore E3001 on line 3"]
    assert [title for title in titles if title.startswith("Ignore")] == ignores  # each its own line's comment


async def test_a_missing_label_is_corrected_or_made(client, tmp_path):
    text = "GOSUB mian\nEND\n#main\nRETURN\n"
    uri = uri_of(tmp_path / "label.mnt")
    diagnostics = await open_document(client, uri, text)
    found = await fixes(client, uri, diagnostics, 0)
    assert set(found) == {"Change to #main", "Create subroutine #mian", "Ignore E3004 on this line"}
    assert applied(text, found["Change to #main"], uri) == "GOSUB main\nEND\n#main\nRETURN\n"
    assert applied(text, found["Create subroutine #mian"], uri) == text + "\n#mian\nRETURN\n"


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # the manual's structure (000:279-295): main program, END, then the subroutines
        pytest.param(
            "GOSUB init\nGOSUB main\nEND\n#init\nRETURN\n",
            "GOSUB init\nGOSUB main\nEND\n#init\nRETURN\n\n#main\nRETURN\n",
            id="after-the-last-return",
        ),
        # a main program that runs to the end of the file would run into it: END first, as 12.4's 2010 asks
        pytest.param("GOSUB main\nPRINT 1\n", "GOSUB main\nPRINT 1\nEND\n\n#main\nRETURN\n", id="no-end"),
        pytest.param(
            "GOSUB main\nGOTO top\n#top\nPRINT 1",
            "GOSUB main\nGOTO top\n#top\nPRINT 1\nEND\n\n#main\nRETURN\n",
            id="goto-target",
        ),
        # an endless main loop never falls through (000:284-290: #main LOOP .. ENDL)
        pytest.param(
            "GOSUB main\nLOOP\n  PRINT 1\nENDL\n", "GOSUB main\nLOOP\n  PRINT 1\nENDL\n\n#main\nRETURN\n", id="loop"
        ),
    ],
)
async def test_a_subroutine_is_created_where_the_program_cannot_run_into_it(client, tmp_path, text, expected):
    uri = uri_of(tmp_path / "create.mnt")
    diagnostics = await open_document(client, uri, text)
    found = await fixes(client, uri, diagnostics, text[: text.index("GOSUB main")].count("\n"))
    assert applied(text, found["Create subroutine #main"], uri) == expected


async def test_then_used_as_a_block_becomes_do(client, tmp_path):
    text = "DIM a\nIF a THEN\n  PRINT 1\nENDIF\n"
    uri = uri_of(tmp_path / "then.mnt")
    diagnostics = await open_document(client, uri, text)
    found = await fixes(client, uri, diagnostics, 3)
    assert applied(text, found["Change THEN to DO"], uri) == "DIM a\nIF a DO\n  PRINT 1\nENDIF\n"


async def test_unreachable_code_is_removed(client, tmp_path):
    text = "GOTO label1\nPRINT 1\nPRINT 2\n#label1\nEND\n"  # the guide's GOTO entry (line 11194)
    uri = uri_of(tmp_path / "dead.mnt")
    diagnostics = await open_document(client, uri, text)
    found = await fixes(client, uri, diagnostics, 1)
    assert applied(text, found["Remove unreachable code"], uri) == "GOTO label1\n#label1\nEND\n"


@pytest.mark.parametrize(
    "line",
    [
        'INPUT "Enter Master Distance", master_dist',  # INPUT reads into a variable (000:12212)
        "FOR master_dist = 1 TO 10 : NEXT",  # a keyword as the loop counter is an error (000:10887, 18449-18451)
    ],
)
async def test_no_keyword_is_offered_where_only_a_variable_can_stand(client, tmp_path, line):
    text = f"{line}\nPRINT master_dist\n"
    uri = uri_of(tmp_path / "variable.mnt")
    diagnostics = await open_document(client, uri, text)
    there = await fixes(client, uri, diagnostics, 0)
    assert "Declare 'master_dist' with DIM" in there and "Replace with MASTERDISTANCE" not in there
    read = await fixes(client, uri, diagnostics, 1)  # read in an expression, the keyword is a likely meaning
    assert "Replace with MASTERDISTANCE" in read
