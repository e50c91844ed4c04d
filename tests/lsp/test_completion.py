"""Completion offers only what is valid where the cursor is."""

from __future__ import annotations

import pytest
from lsprotocol import types

from mintlang.lsp.server import create_server
from tests.lsp.conftest import SHARED, change, corpus, document, open_document, position, uri_of

pytestmark = pytest.mark.asyncio


async def labels_at(client, uri, text, needle, shift=0) -> dict[str, types.CompletionItem]:
    found = await client.text_document_completion_async(
        types.CompletionParams(text_document=document(uri), position=position(text, needle, shift))
    )
    return {item.label: item for item in found.items}


async def test_statement_start_offers_commands_variables_and_snippets(client, tmp_path):
    text = corpus("ch01_l0144_xy_example.mnt") + "DEFINE fast = 10\n\n"
    uri = uri_of(tmp_path / "xy.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, "fast = 10\n", 10)
    assert {"GO", "SPEED", "MOVEA", "xpos", "a", "fast", "FOR … NEXT", "IF … DO … ENDIF"} <= set(items)
    assert items["SPEED"].detail == "parameter, abbreviation SP"
    assert items["FOR … NEXT"].insert_text_format == types.InsertTextFormat.Snippet
    assert "_TRUE" not in items and "init" not in items


async def test_expression_offers_readable_words_only(client, tmp_path):
    text = "DIM a\nDIM b\na = \n"
    uri = uri_of(tmp_path / "expression.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, "a = ", 4)
    assert {"POS", "SIN", "INKEY", "a", "b"} <= set(items)
    assert "GO" not in items and "FOR … NEXT" not in items  # commands and blocks are statements


async def test_a_keyword_whose_entry_lists_no_controller_is_offered_as_mint_check_accepts_it(client, tmp_path):
    # the quick reference ticks no controller for MOVESTATUS (000:17704): hover and mint check take it as
    # available on every controller, and completion offers it likewise
    text = "DIM a\na = \n"
    uri = uri_of(tmp_path / "unlisted.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, "a = ", 4)
    assert {"MOVESTATUS", "AUXENCODERSPEED"} <= set(items)


async def test_labels_after_gosub(client, tmp_path):
    text = corpus("ch03_l0815_main_menu_inkey.mnt") + "GOSUB \n"
    uri = uri_of(tmp_path / "menu.mnt")
    await open_document(client, uri, text)
    assert set(await labels_at(client, uri, text, "GOSUB \n", 6)) == {"mainMenu", "start", "setup"}


async def test_constants_after_underscore(client, tmp_path):
    text = "DIM a\na = _\n"
    uri = uri_of(tmp_path / "constants.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, "_\n", 1)
    assert {"_TRUE", "_FALSE", "_hmPOSITIVE_SWITCH"} <= set(items)
    assert items["_TRUE"].detail == "= 1 — predefined constant"  # a detail is plain text, not Markdown
    assert "SPEED" not in items


async def test_a_v3_file_is_offered_the_v3_constants(client, tmp_path):
    # the v3 guide's table (001:1309-1336): _servo for CONFIG, _limit for ERROR; v4's _cfSERVO is no v3 word
    client.workspace_did_change_configuration(types.DidChangeConfigurationParams(settings={"mint": {"dialect": "v3"}}))
    text = "CONFIG = _\n"
    uri = uri_of(tmp_path / "old.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, "_\n", 1)
    assert {"_servo", "_stepper", "_limit", "_true"} <= set(items)
    assert items["_servo"].detail == "= 1 — Mint v3 predefined constant; Mint v4: _cfSERVO"  # plain text
    assert not {"_cfSERVO", "_TRUE", "_hmPOSITIVE_SWITCH"} & set(items)


async def test_null_is_offered_where_camtable_takes_its_master_table(client, tmp_path):
    # CAMTABLE(axis, positions, NULL) when there is no master distance table (000:7958, 7971)
    text = "DIM myPositions(20)\nCAMTABLE(3, myPositions, N\n"
    uri = uri_of(tmp_path / "cam.mnt")
    await open_document(client, uri, text)
    found = await client.text_document_completion_async(
        types.CompletionParams(text_document=document(uri), position=position(text, ", N", 3))
    )
    assert found.items[0].label == "NULL"
    at_the_positions = await labels_at(client, uri, text, "3, ", 3)
    assert "NULL" not in at_the_positions and "myPositions" in at_the_positions


async def test_event_handlers_after_hash_at_line_start(client, tmp_path):
    text = "END\n#\n"
    uri = uri_of(tmp_path / "events.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, "#", 1)
    assert {"#ONERROR", "#STOP", "#TIMER", "#IN0", "#FASTIN0", "#COMMS1"} <= set(items)
    typed = items["#ONERROR"].text_edit  # replaces the "#" typed, whatever the client takes for a word
    assert (typed.new_text, typed.range.start.character, typed.range.end.character) == ("#ONERROR", 0, 1)


async def test_handlers_the_program_has_are_not_offered_again(client, tmp_path):
    # a second #ONERROR is a label defined twice, "Invalid label" (000:1843-1844, E3004); the one typed is offered
    text = "END\n#ONERROR\nRETURN\n#in1\nRETURN\n#IN2\n"
    uri = uri_of(tmp_path / "handled.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, "#IN2", 4)
    assert {"#IN2", "#IN0", "#STOP"} <= set(items)
    assert not {"#ONERROR", "#IN1"} & set(items)


async def test_a_terminal_number_after_print_hash_gets_no_handler_names(client, tmp_path):
    text = "PRINT #\n"
    uri = uri_of(tmp_path / "terminal.mnt")
    await open_document(client, uri, text)
    assert await labels_at(client, uri, text, "#", 1) == {}


async def test_statement_start_offers_no_functions_operators_or_continuations(client, tmp_path):
    text = "DIM a\n\n"
    uri = uri_of(tmp_path / "start.mnt")
    await open_document(client, uri, text)
    items = set(await labels_at(client, uri, text, "a\n", 2))
    assert {"GO", "PRINT", "a"} <= items
    assert not items & {"SIN", "ABS", "AND", "NOT", "~", "THEN", "TO", "STEP", "USING", "DO", "#", ":"}


# ELSE and ENDIF belong in an IF .. DO (000:11797-11803), NEXT, ENDW, ENDL and UNTIL close their own loops, and
# EXIT leaves any of the four (000:10236-10243): at the start of a statement each is offered only inside its block,
# and a closing word only for the innermost block, the level the last opening word opened (000:1918-1921): ENDW
# in a FOR inside a WHILE, or ENDIF in a REPEAT inside an IF, is the checker's E2012 or E2011.
BLOCK_WORDS = {"ELSE", "ENDIF", "NEXT", "ENDW", "ENDL", "UNTIL", "EXIT"}


@SHARED
@pytest.mark.parametrize(
    ("needle", "words"),
    [
        ("\n\nLOOP", set()),
        ("\n\nENDL", {"ENDL", "EXIT"}),
        ("\n\nIF", set()),
        ("\n\nENDIF", {"ELSE", "ENDIF"}),
        ("\n\nNEXT", {"NEXT", "EXIT"}),
        ("\n\nUNTIL", {"UNTIL", "EXIT"}),
    ],
)
async def test_block_words_only_inside_their_blocks(shared_client, tmp_path, needle, words):
    text = (
        "DIM a\n\nLOOP\n\nENDL\n\nIF a DO\n\nENDIF\n"
        "WHILE a\nFOR a = 1 TO 2\n\nNEXT\nENDW\nIF a DO\nREPEAT\n\nUNTIL a\nENDIF\n"
    )
    uri = uri_of(tmp_path / "blocks.mnt")
    await open_document(shared_client, uri, text)
    items = set(await labels_at(shared_client, uri, text, needle, 1))
    assert items & BLOCK_WORDS == words
    assert {"GO", "PRINT"} <= items


@SHARED
@pytest.mark.parametrize(
    ("needle", "shift", "words"),
    [
        ("\n\nELSE", 1, {"ELSE", "ENDIF"}),  # before the ELSE: it may come here
        ("ELSE\n\nENDIF", 5, {"ENDIF"}),  # after it: an IF .. DO takes one ELSE (000:1593-1600)
        ("  IF a DO\n\n  ENDIF", 10, {"ELSE", "ENDIF"}),  # an IF .. DO in the ELSE part has its own
    ],
)
async def test_else_is_offered_only_before_its_ifs_else(shared_client, tmp_path, needle, shift, words):
    text = "DIM a\nIF a DO\n\nELSE\n\nENDIF\nIF a DO\nELSE\n  IF a DO\n\n  ENDIF\nENDIF\n"
    uri = uri_of(tmp_path / "else.mnt")
    await open_document(shared_client, uri, text)
    assert set(await labels_at(shared_client, uri, text, needle, shift)) & BLOCK_WORDS == words


# The editor asks for completion right after each keystroke, before the server has analysed the new text (the
# pause is a minute here, so no analysis can come in between): the blocks of the last analysis still tell where
# each block word fits while the lines changed since hold none. Lines 0-6 before the edit: a FOR block (1-3), a
# WHILE block (4-6); the edit adds two PRINT lines inside the FOR, moving the WHILE's empty line 5 to 7.
STALE = "DIM a\nFOR a = 1 TO 2\n  a = a\nNEXT\nWHILE a\n\nENDW\n"


async def typed_before_analysis(client, tmp_path, at: int, typed: str, line: int) -> set[str]:
    """The labels offered at the start of ``line`` once ``typed`` is inserted at the start of line ``at`` of
    ``STALE``, asked at once as an editor asks."""
    client.workspace_did_change_configuration(
        types.DidChangeConfigurationParams(settings={"mint": {"debounceMs": 60_000}})
    )
    uri = uri_of(tmp_path / "stale.mnt")
    await open_document(client, uri, STALE)
    change(client, uri, 2, ((at, 0), (at, 0)), typed)
    found = await client.text_document_completion_async(
        types.CompletionParams(text_document=document(uri), position=types.Position(line=line, character=0))
    )
    return {item.label for item in found.items}


@pytest.mark.parametrize(
    ("line", "words"),
    [
        (7, {"ENDW", "EXIT"}),  # below the change: the WHILE, moved down two lines
        (3, {"NEXT", "EXIT"}),  # a changed line: the FOR around it
        (0, set()),  # above the change: no block
    ],
)
async def test_block_words_fit_the_text_typed_since_the_last_analysis(client, tmp_path, line, words):
    assert await typed_before_analysis(client, tmp_path, 2, "  PRINT a\n  PRINT a\n", line) & BLOCK_WORDS == words


async def test_a_block_word_typed_since_the_last_analysis_leaves_every_block_word_offered(client, tmp_path):
    # An IF .. DO typed into the WHILE opens a block the last analysis never saw: ELSE and ENDIF fit on the
    # line below it as ENDW and EXIT do, and what the new text holds is not known until it is analysed.
    assert {"ELSE", "ENDIF", "ENDW", "EXIT"} <= await typed_before_analysis(client, tmp_path, 5, "  IF a DO\n", 6)


@SHARED
@pytest.mark.parametrize(
    ("line", "reason"),
    [
        ("DIM ", "a new name is declared"),
        ("DEFINE ", "a new name is defined"),
        ("a = 1.", "decimals follow"),
        ("a = 'b", "inside a character constant"),
    ],
)
async def test_nothing_where_no_word_of_the_list_can_go(shared_client, tmp_path, line, reason):
    text = f"DIM a\n{line}\n"
    uri = uri_of(tmp_path / "nothing.mnt")
    await open_document(shared_client, uri, text)
    assert await labels_at(shared_client, uri, text, line, len(line)) == {}, reason


async def test_after_an_operand_the_operators_and_continuations(client, tmp_path):
    text = "DIM a\nIF a \n"
    uri = uri_of(tmp_path / "operand.mnt")
    await open_document(client, uri, text)
    items = set(await labels_at(client, uri, text, "IF a ", 5))
    assert {"AND", "OR", "XOR", "MOD", "THEN", "DO"} <= items
    assert not items & {"POS", "SIN", "a"}


# After an operand a statement goes on only with its own words: IF <condition> THEN or DO (000:11797,
# 11853), FOR <variable> = <expression1> TO <expression2> {STEP <expression3>} (000:10887), and USING
# once after the values of PRINT, INPUT and LINE (000:15295, 12212, 13657).
STATEMENT_WORDS = {"THEN", "DO", "TO", "STEP", "USING"}


@SHARED
@pytest.mark.parametrize(
    ("line", "words"),
    [
        ("IF a ", {"THEN", "DO"}),
        ("IF a > 1 AND a ", {"THEN", "DO"}),
        ("FOR a = 1 ", {"TO"}),
        ("FOR a = 1 TO 10 ", {"STEP"}),
        ("FOR a = 1 TO 10 STEP 2 ", set()),
        ("PRINT a ", {"USING"}),
        ("? a ", {"USING"}),
        ("INPUT a ", {"USING"}),
        ("LINE 2, a ", {"USING"}),
        ("PRINT a USING 5 ", set()),
        ("IF a THEN PRINT a ", {"USING"}),
        ("IF a THEN a = a ", set()),
        ("WHILE a ", set()),
        ("PAUSE a ", set()),
        ("a = a ", set()),
        ("REPEAT : UNTIL a ", set()),
    ],
)
async def test_after_an_operand_only_the_words_of_the_statement_being_written(shared_client, tmp_path, line, words):
    text = f"DIM a\n{line}\n"
    uri = uri_of(tmp_path / "statement.mnt")
    await open_document(shared_client, uri, text)
    items = set(await labels_at(shared_client, uri, text, line, len(line)))
    assert {"AND", "OR", "MOD"} <= items
    assert items & STATEMENT_WORDS == words


@SHARED
@pytest.mark.parametrize(
    "line",
    [
        pytest.param("INPUT ", id="input"),
        pytest.param('INPUT "Count? ", ', id="after-the-prompt"),
        pytest.param("INPUT #1 ", id="after-the-terminal"),
        pytest.param('INPUT #3 "Count? ", ', id="after-terminal-and-prompt"),
        pytest.param("IF a THEN INPUT ", id="after-then"),
    ],
)
async def test_input_is_offered_the_variables_it_can_fill_only(shared_client, tmp_path, line):
    # INPUT {#<terminal>} {string,} variable (000:12212): a name to fill, neither a function nor a keyword read
    text = f"DIM a\nDIM table(4)\n{line}\n"
    uri = uri_of(tmp_path / "input.mnt")
    await open_document(shared_client, uri, text)
    assert set(await labels_at(shared_client, uri, text, line, len(line))) == {"a", "table"}


async def test_symbol_details_are_plain_text_and_the_description_is_markdown(client, tmp_path):
    text = "DIM a\nDEFINE fast = SPEED.0 = 500\na = \n"
    uri = uri_of(tmp_path / "details.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, "a = ", 4)
    assert (items["a"].detail, items["fast"].detail) == ("variable", "macro")
    fast = await client.completion_item_resolve_async(items["fast"])  # described when shown
    assert "DEFINE fast = SPEED.0 = 500" in fast.documentation.value  # as written, not re-spaced
    variable = await client.completion_item_resolve_async(items["a"])
    assert variable.documentation.value.startswith("**a** — variable, declared at line 1")


async def test_nothing_inside_comments_and_strings(client, tmp_path):
    text = 'REM speed \nPRINT "spe"\n'
    uri = uri_of(tmp_path / "quiet.mnt")
    await open_document(client, uri, text)
    assert await labels_at(client, uri, text, "speed", 3) == {}
    assert await labels_at(client, uri, text, 'spe"', 2) == {}


async def test_resolve_adds_the_manual_entry(client, tmp_path):
    text = "\n"
    uri = uri_of(tmp_path / "resolve.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, "\n")
    resolved = await client.completion_item_resolve_async(items["HOMESPEED"])
    assert "**HOMESPEED**" in resolved.documentation.value


async def test_completion_while_typing_uses_the_line_as_typed(client, tmp_path):
    text = corpus("ch03_l0815_main_menu_inkey.mnt")
    uri = uri_of(tmp_path / "typing.mnt")
    await open_document(client, uri, text)
    end = len(text.splitlines())
    change(client, uri, 2, ((end, 0), (end, 0)), "GOSUB s")
    found = await client.text_document_completion_async(
        types.CompletionParams(text_document=document(uri), position=types.Position(line=end, character=7))
    )
    assert {item.label for item in found.items} == {"mainMenu", "start", "setup"}


@SHARED
@pytest.mark.parametrize("line", ["RETURN ", "END ", "ENDIF ", "NEXT ", "GO ", "SPEED ", "DIM _"])
async def test_nothing_after_a_complete_statement_or_a_command_awaiting_its_axes(shared_client, tmp_path, line):
    text = f"DIM a\n{line}\n"
    uri = uri_of(tmp_path / "complete.mnt")
    await open_document(shared_client, uri, text)
    assert await labels_at(shared_client, uri, text, line, len(line)) == {}


async def test_a_keyword_read_is_an_operand_and_binary_operators_wait_for_one(client, tmp_path):
    text = "DIM a\nIF IN3 \na = \n"
    uri = uri_of(tmp_path / "operands.mnt")
    await open_document(client, uri, text)
    after = set(await labels_at(client, uri, text, "IF IN3 ", 7))
    assert {"AND", "OR", "THEN", "DO"} <= after and not after & {"NOT", "POS", "a"}
    before = set(await labels_at(client, uri, text, "a = ", 4))
    assert {"NOT", "POS", "a"} <= before and not before & {"AND", "OR", "MOD", "XOR"}


# The manual's macros for axes (3.5): "DEFINE g1 = [0,1,2,3] / SF.g1 = 10;" and "DEFINE xAxis = 0 /
# MOVER..xAxis = 10", where one dot before a macro is only a delimiter.
AXIS_MACROS = "DEFINE g1 = [0,1,2,3]\nDEFINE g2 = [4,5,6,7]\nDEFINE xAxis = 0\nDEFINE far = 40\nDIM a\n"


async def test_after_an_axis_dot_the_axes_of_the_controller_and_the_macros_naming_them(client, tmp_path):
    text = AXIS_MACROS + "SPEED.\n"
    uri = uri_of(tmp_path / "dot.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, "SPEED.", 6)
    numbers = [label for label, item in items.items() if item.kind == types.CompletionItemKind.Value]
    assert numbers == [str(axis) for axis in range(12)]  # NextMove PCI: axes 0 to 11
    assert items["3"].detail == "axis 3"
    assert set(items) - set(numbers) == {"g1", "g2", "xAxis"}  # far names no axis of the controller
    assert items["g1"].text_edit.new_text == "g1"  # SF.g1: the list is the selector
    assert items["xAxis"].text_edit.new_text == ".xAxis"  # MOVER..xAxis: the first dot only delimits
    assert items["g2"].detail == "macro for axes 4, 5, 6, 7"


async def test_after_a_channel_dot_the_channels_and_after_two_dots_the_macros(client, tmp_path):
    text = AXIS_MACROS + "a = IN.\nMOVER..\n"
    uri = uri_of(tmp_path / "channels.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, "IN.", 3)
    numbers = [label for label, item in items.items() if item.kind == types.CompletionItemKind.Value]
    assert numbers == [str(channel) for channel in range(60)] and items["7"].detail == "input 7"
    assert set(items) - set(numbers) == {"xAxis", "far"}  # one number each: a list selects axes only
    after_two = await labels_at(client, uri, text, "MOVER..", 7)
    assert set(after_two) == {"xAxis"} and after_two["xAxis"].text_edit.new_text == "xAxis"


async def test_the_axes_follow_the_controller(client, tmp_path):
    client.workspace_did_change_configuration(
        types.DidChangeConfigurationParams(settings={"mint": {"controller": "nextmove-bx"}})
    )
    text = "SPEED.\nDIM a\na = ENCODER.\n"
    uri = uri_of(tmp_path / "bx.mnt")
    await open_document(client, uri, text)
    assert list(await labels_at(client, uri, text, "SPEED.", 6)) == [str(axis) for axis in range(8)]
    assert list(await labels_at(client, uri, text, "ENCODER.", 8)) == ["0", "1", "2", "3"]


async def test_the_dot_triggers_completion(client, tmp_path):
    text = "SPEED\n"
    uri = uri_of(tmp_path / "trigger.mnt")
    await open_document(client, uri, text)
    change(client, uri, 2, ((0, 5), (0, 5)), ".")
    found = await client.text_document_completion_async(
        types.CompletionParams(
            text_document=document(uri),
            position=types.Position(line=0, character=6),
            context=types.CompletionContext(
                trigger_kind=types.CompletionTriggerKind.TriggerCharacter, trigger_character="."
            ),
        )
    )
    assert "0" in {item.label for item in found.items}
    assert "." in initialized().completion_provider.trigger_characters


def initialized() -> types.ServerCapabilities:
    """The capabilities the server announces, from its initialize handler run in this process."""
    steps = create_server().protocol.lsp_initialize(types.InitializeParams(capabilities=types.ClientCapabilities()))
    try:
        while True:
            next(steps)
    except StopIteration as answer:
        return answer.value.capabilities
