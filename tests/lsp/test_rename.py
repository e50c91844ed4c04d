"""Rename: every occurrence, keywords refused, ten-character collisions rejected."""

from __future__ import annotations

import re
import sys

import pytest
from lsprotocol import types
from pygls.exceptions import JsonRpcException
from pygls.lsp.client import LanguageClient

from tests.lsp.conftest import SHARED, corpus, document, open_document, position, uri_of
from tests.lsp.test_formatting import apply

pytestmark = pytest.mark.asyncio
XY = corpus("ch01_l0144_xy_example.mnt")


async def test_prepare_rename(client, tmp_path):
    uri = uri_of(tmp_path / "xy.mnt")
    await open_document(client, uri, XY)
    prepared = await client.text_document_prepare_rename_async(
        types.PrepareRenameParams(text_document=document(uri), position=position(XY, "#init", 2))
    )
    assert prepared.placeholder == "init"
    assert prepared.range.start == types.Position(line=13, character=1)
    with pytest.raises(JsonRpcException, match="keyword"):
        await client.text_document_prepare_rename_async(
            types.PrepareRenameParams(text_document=document(uri), position=position(XY, "MOVEA"))
        )


async def test_rename_an_array_and_a_label(client, tmp_path):
    uri = uri_of(tmp_path / "xy.mnt")
    await open_document(client, uri, XY)
    edit = await client.text_document_rename_async(
        types.RenameParams(text_document=document(uri), position=position(XY, "xpos(a)"), new_name="x_positions")
    )
    assert sorted(e.range.start.line for e in edit.changes[uri]) == [6, 27]
    assert {e.new_text for e in edit.changes[uri]} == {"x_positions"}
    edit = await client.text_document_rename_async(
        types.RenameParams(text_document=document(uri), position=position(XY, "GOSUB init", 7), new_name="#setup")
    )
    assert sorted((e.range.start.line, e.range.start.character) for e in edit.changes[uri]) == [
        (9, 6),
        (13, 1),
        (35, 6),
    ]


@SHARED
@pytest.mark.parametrize(
    ("new_name", "reason"),
    [
        ("ypos", "'ypos' is already the name of the array 'ypos'$"),
        ("YPOS", "'YPOS' is already the name of the array 'ypos'$"),  # the controller reads names without case
        ("SPEED", "the Mint keyword SPEED"),
        ("two words", "not a valid"),
        ("__pos", "not a valid"),  # _ begins a name only before a letter or digit (000:882-884)
    ],
)
async def test_rename_refusals(shared_client, tmp_path, new_name, reason):
    uri = uri_of(tmp_path / "xy.mnt")
    await open_document(shared_client, uri, XY)
    with pytest.raises(JsonRpcException, match=reason):
        await shared_client.text_document_rename_async(
            types.RenameParams(text_document=document(uri), position=position(XY, "xpos(a)"), new_name=new_name)
        )


async def test_collision_in_the_first_ten_characters(client, tmp_path):
    text = "DIM axis_speed_x\nDIM count\ncount = axis_speed_x\n"
    uri = uri_of(tmp_path / "ten.mnt")
    await open_document(client, uri, text)
    with pytest.raises(JsonRpcException, match="first ten characters"):
        await client.text_document_rename_async(
            types.RenameParams(text_document=document(uri), position=position(text, "count"), new_name="axis_speed_y")
        )


# A macro's text replaces its name wherever the name is found (000:9110), after GOSUB as anywhere: a label and a
# macro of one name would make GOSUB fast into GOSUB SPEED.0 = 100. Keywords, their abbreviations and the
# constants are no names (000:1475).
LABEL_REPLACED = ": the controller would put the macro's text in place of the label's name"
MACRO_AND_LABEL = "DEFINE fast = SPEED.0 = 100\nGOSUB init\nEND\n#init\nfast\nRETURN\n"


@SHARED
@pytest.mark.parametrize(
    ("at", "new_name", "refusal"),
    [
        (
            "GOSUB init",
            "fast",
            "'fast' is the name of the macro 'fast'" + LABEL_REPLACED,
        ),
        (
            "GOSUB init",
            "#FAST",
            "'FAST' is the name of the macro 'fast'" + LABEL_REPLACED,
        ),
        (
            "DEFINE fast",
            "init",
            "'init' is the name of the label #init" + LABEL_REPLACED,
        ),
        ("GOSUB init", "speed", "'speed' is the Mint keyword SPEED: the label cannot take its name"),
        ("GOSUB init", "Loop", "'Loop' is the Mint keyword LOOP: the label cannot take its name"),
        ("GOSUB init", "sp", "'sp' is the abbreviation of SPEED: the label cannot take its name"),
        ("DEFINE fast", "NULL", "'NULL' is the Mint constant NULL: the macro cannot take its name"),
        ("GOSUB init", "_true", "'_true' is the Mint constant _TRUE: the label cannot take its name"),
        ("GOSUB init", "9lives", "'9lives' is not a valid Mint name: a name starts with a letter"),
        ("DEFINE fast", "123", "'123' is a number: the macro cannot take its name"),  # not "the keyword 123"
    ],
)
async def test_a_label_or_macro_does_not_take_a_macros_a_labels_or_a_keywords_name(
    shared_client, tmp_path, at, new_name, refusal
):
    uri = uri_of(tmp_path / "macro_and_label.mnt")
    await open_document(shared_client, uri, MACRO_AND_LABEL)
    where = position(MACRO_AND_LABEL, at, len(at) - 1)
    with pytest.raises(JsonRpcException, match=re.escape(refusal)):
        await shared_client.text_document_rename_async(
            types.RenameParams(text_document=document(uri), position=where, new_name=new_name)
        )


MACRO = "DIM target = 10\nDEFINE fast = SPEED.0 = target\nfast\nPRINT target\n"


async def test_a_variable_a_macro_mentions_is_renamed_in_the_macros_body_not_at_its_uses(client, tmp_path):
    uri = uri_of(tmp_path / "macro.mnt")
    await open_document(client, uri, MACRO)
    edit = await client.text_document_rename_async(
        types.RenameParams(text_document=document(uri), position=position(MACRO, "PRINT target", 7), new_name="goal")
    )
    places = sorted((e.range.start.line, e.range.start.character, e.range.end.character) for e in edit.changes[uri])
    assert places == [(0, 4, 10), (1, 24, 30), (3, 6, 12)]  # the DIM, the macro's body, the PRINT: never "fast"
    prepared = await client.text_document_prepare_rename_async(
        types.PrepareRenameParams(text_document=document(uri), position=position(MACRO, "= target", 3))
    )
    assert prepared.placeholder == "target"


@SHARED
@pytest.mark.parametrize("new_name", ["onerror", "#TIMER", "fastin0"])
async def test_a_subroutine_is_not_renamed_into_an_event_handler(shared_client, tmp_path, new_name):
    uri = uri_of(tmp_path / "xy.mnt")
    await open_document(shared_client, uri, XY)
    with pytest.raises(JsonRpcException, match="event handler"):
        await shared_client.text_document_rename_async(
            types.RenameParams(text_document=document(uri), position=position(XY, "#init", 2), new_name=new_name)
        )


async def test_an_event_handler_keeps_its_name(client, tmp_path):
    text = XY + "#ONERROR\nRETURN\n"
    uri = uri_of(tmp_path / "xy.mnt")
    await open_document(client, uri, text)
    with pytest.raises(JsonRpcException, match="event handler"):
        await client.text_document_prepare_rename_async(
            types.PrepareRenameParams(text_document=document(uri), position=position(text, "#ONERROR", 3))
        )


@SHARED
@pytest.mark.parametrize(
    ("label", "at"),
    [
        pytest.param("worker", "#worker", id="a-name"),
        pytest.param("worker", "GOSUB worker", id="from-the-macros-body"),
        # a label may be spelt as a keyword or a function (GOSUB takes NAME | KEYWORD | FUNCTION | NUMBER, as the
        # checker reads it): conveyor.mnt's #home, in a macro's text as anywhere
        pytest.param("home", "#home", id="a-keywords-spelling"),
        pytest.param("home", "GOSUB home", id="a-keywords-spelling-from-the-macros-body"),
        pytest.param("abs", "#abs", id="a-functions-spelling"),
    ],
)
async def test_a_label_a_macro_jumps_to_is_renamed_in_the_macros_body_too(shared_client, tmp_path, label, at):
    text = f"DEFINE doit = GOSUB {label}\ndoit\nEND\n#{label}\nRETURN\n"
    uri = uri_of(tmp_path / "jump.mnt")
    await open_document(shared_client, uri, text)
    edit = await shared_client.text_document_rename_async(
        types.RenameParams(text_document=document(uri), position=position(text, at, len(at) - 1), new_name="job")
    )
    places = sorted((e.range.start.line, e.range.start.character, e.range.end.character) for e in edit.changes[uri])
    assert places == [(0, 20, 20 + len(label)), (3, 1, 1 + len(label))]


EXPECTING = (
    "REM @expect count = 3\n"
    'REM @expect terminal contains "count"\n'
    "DIM count = 3 : REM @expect COUNT >= 1 at end\n"
    "DIM table(2) = 1, 2 : REM count stays a word here\n"
    "REM @expect no spare\n"
    "DIM spare\n"
    'PRINT "count", count, table(2), spare\n'
    "REM @expect table(2) = 2\n"
)


@pytest.mark.parametrize(
    ("needle", "new_name", "renamed"),
    [
        # An expectation reads a variable or array element by name (runtime/scenario/README.md, "Directives in
        # the program": count >= 3, table(3), no X); the terminal's text and other comments are no names.
        (
            "count = 3 :",
            "total",
            EXPECTING.replace("@expect count", "@expect total")
            .replace("@expect COUNT", "@expect total")
            .replace("DIM count", "DIM total")
            .replace(", count,", ", total,"),
        ),
        ("table(2) =", "tbl", EXPECTING.replace("table(2)", "tbl(2)")),
    ],
)
async def test_a_variable_or_array_is_renamed_in_the_programs_expectations(client, tmp_path, needle, new_name, renamed):
    uri = uri_of(tmp_path / "expecting.mnt")
    await open_document(client, uri, EXPECTING)
    edit = await client.text_document_rename_async(
        types.RenameParams(text_document=document(uri), position=position(EXPECTING, needle), new_name=new_name)
    )
    assert apply(EXPECTING, edit.changes[uri]) == renamed


SCENARIO = (
    '[[expect]]\nwhat = "count"\nequals = 3\n\n'
    '[[expect]]\nwhat = "POS.0"\nequals = 0\n\n'
    '[[expect]]\nterminal_contains = "count"\n'
)


COUNTED = "DIM count = 3\nPRINT count\n"


async def _count_renamed_beside(client, tmp_path, scenario_name: str, scenario: str) -> types.WorkspaceEdit:
    """``count`` of ``cell.mnt`` renamed to ``total``, with ``scenario`` written beside it as ``scenario_name``."""
    (tmp_path / scenario_name).write_text(scenario, encoding="utf-8")
    uri = uri_of(tmp_path / "cell.mnt")
    await open_document(client, uri, COUNTED)
    return await client.text_document_rename_async(
        types.RenameParams(text_document=document(uri), position=position(COUNTED, "count"), new_name="total")
    )


async def test_a_variable_is_renamed_in_the_scenario_file_beside_the_program(client, tmp_path):
    """``cell.scenario.toml`` beside ``cell.mnt`` is its test (README, mint test), any case; each expectation
    names what it reads in ``what`` (runtime/scenario/README.md): a keyword or the terminal's text is no name."""
    edit = await _count_renamed_beside(client, tmp_path, "Cell.Scenario.toml", SCENARIO)
    assert apply(COUNTED, edit.changes[uri_of(tmp_path / "cell.mnt")]) == "DIM total = 3\nPRINT total\n"
    scenario = edit.changes[uri_of(tmp_path / "Cell.Scenario.toml")]
    assert apply(SCENARIO, scenario) == SCENARIO.replace('what = "count"', 'what = "total"')


async def test_a_variable_is_renamed_in_the_scenario_files_inline_tables_too(client, tmp_path):
    """TOML writes the same expectations as inline tables; the terminal's text still names nothing."""
    scenario = 'expect = [{ what = "count", equals = 3 }, { terminal_contains = "count", what = "POS.0" }]\n'
    edit = await _count_renamed_beside(client, tmp_path, "cell.scenario.toml", scenario)
    changes = edit.changes[uri_of(tmp_path / "cell.scenario.toml")]
    assert apply(scenario, changes) == scenario.replace('what = "count"', 'what = "total"')


async def test_the_scenario_files_edit_counts_columns_as_the_client_does(client, tmp_path):
    """LSP columns are UTF-16 code units by default: a character outside the BMP before the name is two."""
    scenario = 'expect = [{ terminal_contains = "\U0001d465", what = "count", equals = 3 }]\n'
    edit = await _count_renamed_beside(client, tmp_path, "cell.scenario.toml", scenario)
    (change,) = edit.changes[uri_of(tmp_path / "cell.scenario.toml")]
    column = scenario.index('"count"') + 1 + 1  # past the quote, and the second unit of U+1D465
    assert (change.range.start.character, change.range.end.character) == (column, column + len("count"))


async def test_a_refused_rename_is_an_answer_not_a_logged_fault(tmp_path):
    log = tmp_path / "server.log"
    client = LanguageClient("refusals", "1")
    await client.start_io(sys.executable, "-m", "mintlang.lsp", "--log-file", str(log))
    await client.initialize_async(types.InitializeParams(capabilities=types.ClientCapabilities()))
    uri = uri_of(tmp_path / "xy.mnt")
    opened = types.TextDocumentItem(uri=uri, language_id="mint", version=1, text=XY)
    client.text_document_did_open(types.DidOpenTextDocumentParams(text_document=opened))
    with pytest.raises(JsonRpcException, match="keyword"):
        await client.text_document_prepare_rename_async(
            types.PrepareRenameParams(text_document=document(uri), position=position(XY, "MOVEA"))
        )
    await client.shutdown_async(None)
    client.exit(None)
    await client.stop()
    assert "Traceback" not in log.read_text(encoding="utf-8")


# The manual's example of two spellings that are one variable (3.2.5): "DIM thisIsAVariable1 /
# DIM thisIsAVaraible2 will only define one variable of the name thisIsAVar".
TWO_SPELLINGS = "DIM thisIsAVariable1\nthisIsAVaraible2 = 5\nPRINT thisIsAVariable1\n"


async def test_a_rename_merging_two_spellings_needs_confirmation(client, tmp_path):
    uri = uri_of(tmp_path / "spellings.mnt")
    await open_document(client, uri, TWO_SPELLINGS)
    edit = await client.text_document_rename_async(
        types.RenameParams(
            text_document=document(uri), position=position(TWO_SPELLINGS, "PRINT t", 7), new_name="level"
        )
    )
    assert edit.changes is None  # only annotated edits, which the client must have the user confirm
    [changed] = edit.document_changes
    assert (changed.text_document.uri, changed.text_document.version) == (uri, 1)
    assert [(e.range.start.line, e.new_text, e.annotation_id) for e in changed.edits] == [
        (line, "level", "mint.mergeSpellings") for line in (0, 1, 2)
    ]
    annotation = edit.change_annotations["mint.mergeSpellings"]
    assert annotation.needs_confirmation
    assert annotation.description.startswith("'thisIsAVariable1' and 'thisIsAVaraible2' are one name")


async def test_one_spelling_in_two_cases_is_renamed_without_a_question(client, tmp_path):
    text = "DIM count\nCOUNT = 1\n"
    uri = uri_of(tmp_path / "case.mnt")
    await open_document(client, uri, text)
    edit = await client.text_document_rename_async(
        types.RenameParams(text_document=document(uri), position=position(text, "count"), new_name="total")
    )
    assert len(edit.changes[uri]) == 2 and edit.change_annotations is None


@pytest.mark.parametrize(("answer", "renamed"), [("Rename all", True), ("Cancel", False), (None, False)])
async def test_a_client_without_annotations_is_asked_first(tmp_path, answer, renamed):
    client = LanguageClient("asked", "1")
    questions: list[str] = []

    @client.feature(types.WINDOW_SHOW_MESSAGE_REQUEST)
    def ask(params: types.ShowMessageRequestParams) -> types.MessageActionItem | None:
        questions.append(params.message)
        return types.MessageActionItem(title=answer) if answer else None

    await client.start_io(sys.executable, "-m", "mintlang.lsp")
    await client.initialize_async(types.InitializeParams(capabilities=types.ClientCapabilities()))
    uri = uri_of(tmp_path / "spellings.mnt")
    opened = types.TextDocumentItem(uri=uri, language_id="mint", version=1, text=TWO_SPELLINGS)
    client.text_document_did_open(types.DidOpenTextDocumentParams(text_document=opened))
    params = types.RenameParams(
        text_document=document(uri), position=position(TWO_SPELLINGS, "PRINT t", 7), new_name="level"
    )
    try:
        if renamed:
            edit = await client.text_document_rename_async(params)
            assert len(edit.changes[uri]) == 3
        else:
            with pytest.raises(JsonRpcException, match="Rename cancelled"):
                await client.text_document_rename_async(params)
    finally:
        await client.shutdown_async(None)
        client.exit(None)
        await client.stop()
    assert len(questions) == 1 and "are one name to the controller" in questions[0]


async def test_a_label_renamed_to_another_labels_name_names_that_label(client, tmp_path):
    text = "GOSUB first\nGOSUB second\nEND\n#first\nRETURN\n#second\nRETURN\n"
    uri = uri_of(tmp_path / "labels.mnt")
    await open_document(client, uri, text)
    with pytest.raises(JsonRpcException, match=r"^'Second' is already the name of the label #second$"):
        await client.text_document_rename_async(
            types.RenameParams(text_document=document(uri), position=position(text, "first"), new_name="Second")
        )


async def test_a_label_may_be_named_by_digits(client, tmp_path):
    """A label is any combination of alphanumeric characters (000:1843): ``#123``, called by ``GOSUB 123``."""
    uri = uri_of(tmp_path / "digits.mnt")
    await open_document(client, uri, MACRO_AND_LABEL)
    where = position(MACRO_AND_LABEL, "GOSUB init", len("GOSUB i"))
    edit = await client.text_document_rename_async(
        types.RenameParams(text_document=document(uri), position=where, new_name="123")
    )
    assert (
        apply(MACRO_AND_LABEL, edit.changes[uri]) == "DEFINE fast = SPEED.0 = 100\nGOSUB 123\nEND\n#123\nfast\nRETURN\n"
    )
