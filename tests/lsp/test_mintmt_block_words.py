"""MintMT's own spellings in the editor: hover and completion know ``Loop … End Loop``, ``If … Then … End If``,
``Event NAME … End Event`` and ``Startup … End Startup`` as MintMT writes them (the move buffer and comms notes),
signature help and completion write a keyword's axes in round brackets, and the outline ends a subroutine
before the Event block after it."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from tests.lsp import test_mintmt
from tests.lsp.conftest import document, open_document, position

pytestmark = pytest.mark.asyncio
client = test_mintmt.client  # the server reading each file's dialect from its text (mint.dialect = auto)

# The shape of the move buffer note's listing (004:98-133) with the comms note's event (002:82-84).
PROGRAM = (
    "DIM a\n"
    "Loop\n"
    "  If COMMS(1) = 1 Then\n"
    "    GO(0)\n"
    "  End If\n"
    "End Loop\n"
    "Event Comms1\n"
    "  JOG(0) = comms(1)\n"
    "End Event\n"
    "Startup\n"
    "  MOVEBUFFERSIZE(0) = 20\n"
    "End Startup\n"
)


async def _hover(client: LanguageClient, uri: str, text: str, needle: str, shift: int = 1) -> str:
    found = await client.text_document_hover_async(
        types.HoverParams(text_document=document(uri), position=position(text, needle, shift))
    )
    assert isinstance(found, types.Hover) and isinstance(found.contents, types.MarkupContent), needle
    return found.contents.value


async def _labels(
    client: LanguageClient, uri: str, text: str, needle: str, shift: int
) -> dict[str, types.CompletionItem]:
    found = await client.text_document_completion_async(
        types.CompletionParams(text_document=document(uri), position=position(text, needle, shift))
    )
    items = found.items if isinstance(found, types.CompletionList) else found or []
    return {item.label: item for item in items}


async def test_block_words_are_described_as_mintmt_writes_them(client: LanguageClient) -> None:
    uri = "file:///work/blocks.mnt"
    await open_document(client, uri, PROGRAM)
    for needle, block in (
        ("Loop\n", "Loop\n  {statements}\nEnd Loop"),
        ("End Loop", "Loop\n  {statements}\nEnd Loop"),
        ("Then", "If <condition> Then\n  {statements}\nEnd If"),
        ("End If", "If <condition> Then\n  {statements}\nEnd If"),
        ("Event Comms1", "Event NAME\n  {statements}\nEnd Event"),
        ("End Event", "Event NAME\n  {statements}\nEnd Event"),
        ("Startup\n", "Startup\n  {statements}\nEnd Startup"),
        ("End Startup", "Startup\n  {statements}\nEnd Startup"),
    ):
        text = await _hover(client, uri, PROGRAM, needle)
        spelling = needle.split(" Comms1")[0].strip()
        assert text.startswith(f"**{spelling}**") and f"```mint\n{block}\n```" in text, needle
        assert "ENDL\n" not in text and "DO\n" not in text  # v4's spellings are not MintMT's
    assert "power" in await _hover(client, uri, PROGRAM, "Startup\n")  # 004:128: run at power-up
    # If .. Then on one line (002:50) or opening a block up to End If (002:64-68), never v4's DO and ENDIF
    text = await _hover(client, uri, PROGRAM, "If COMMS")
    assert (
        text.startswith("**If** — MintMT block") and "```mint\nIf <condition> Then\n  {statements}\nEnd If\n```" in text
    )
    assert "ENDIF\n" not in text and "DO\n" not in text


async def test_the_event_a_block_handles_is_described(client: LanguageClient) -> None:
    uri = "file:///work/event.mnt"
    await open_document(client, uri, PROGRAM)
    text = await _hover(client, uri, PROGRAM, "Comms1", 2)
    assert text.startswith("**Comms1** — MintMT event") and "comms location 1" in text  # 002:19


async def test_completion_offers_mintmt_block_words_and_snippets_not_v4_closers(client: LanguageClient) -> None:
    uri = "file:///work/complete.mnt"
    text = PROGRAM.replace("    GO(0)\n", "    GO(0)\n    \n")
    await open_document(client, uri, text)
    items = await _labels(client, uri, text, "GO(0)\n    \n", 10)
    snippets = {"Loop … End Loop", "If … Then … End If"}
    assert {"End If"} | snippets | {"WHILE", "EXIT", "WHILE … ENDW", "FOR … NEXT"} <= set(items)
    assert "ENDW" not in items  # no While is open here
    assert "End Loop" not in items  # the If inside the Loop is open: End Loop here is E2014, as ENDL in v4
    assert not {"ENDL", "ENDIF", "LOOP … ENDL", "IF … DO … ENDIF"} & set(items)
    assert items["Loop … End Loop"].insert_text == "Loop\n\t$0\nEnd Loop"


# Where each of MintMT's block words may start a statement: a closer inside its own block (004:102-125 closes
# the If with End If, the Loop with End Loop, 002:82-84 the Event with End Event, 004:129-133 Startup with End
# Startup) when it is the innermost open (as in v4, 000:1918-1921), Event and Startup in no other block (MT-13).
BLOCK_WORDS = {"End Loop", "End If", "Event", "End Event", "Startup", "End Startup"}
NESTED = (
    "DIM a\n"
    "Loop\n"
    "  \n"  # in the Loop
    "  If a = 1 Then\n"
    "    \n"  # in the If, in the Loop
    "  End If\n"
    "End Loop\n"
    "\n"  # outside every block
    "Event Comms1\n"
    "  \n"  # in the Event
    "End Event\n"
    "Startup\n"
    "  \n"  # in the Startup block
    "End Startup\n"
)


@pytest.mark.parametrize(
    ("line", "offered"),
    [
        (2, {"End Loop"}),
        (4, {"End If"}),
        (7, {"Event", "Startup", "Event … End Event", "Startup … End Startup"}),
        (9, {"End Event"}),
        (12, {"End Startup"}),
    ],
)
async def test_mintmt_block_words_are_offered_only_where_they_can_stand(
    client: LanguageClient, line: int, offered: set[str]
) -> None:
    uri = "file:///work/nested.mnt"
    await open_document(client, uri, NESTED)
    cursor = types.Position(line=line, character=len(NESTED.splitlines()[line]))
    found = await client.text_document_completion_async(
        types.CompletionParams(text_document=document(uri), position=cursor)
    )
    labels = {item.label for item in found.items}
    assert labels & (BLOCK_WORDS | {"Event … End Event", "Startup … End Startup"}) == offered


async def test_after_event_the_events_a_block_can_handle_are_offered(client: LanguageClient) -> None:
    # MT-13: a host's write to comms locations 1 to 5 (002:19) and MOVEBUFFERLOW (004:114)
    uri = "file:///work/event_names.mnt"
    text = "Loop\nEnd Loop\nEvent \n"
    await open_document(client, uri, text)
    items = await _labels(client, uri, text, "Event \n", 6)
    # first, as the notes spell them; v4's events follow (test_an_event_block_naming_a_v4_event.py)
    assert list(items)[:6] == ["Comms1", "Comms2", "Comms3", "Comms4", "Comms5", "MOVEBUFFERLOW"]
    assert "comms location 3" in items["Comms3"].documentation.value


async def test_v4_files_keep_v4_closers(client: LanguageClient) -> None:
    uri = "file:///work/v4.mnt"
    text = "LOOP\n  GO.0\n  \nENDL\n"
    await open_document(client, uri, text)
    items = await _labels(client, uri, text, "GO.0\n  \n", 7)
    assert {"ENDL", "LOOP … ENDL", "IF … DO … ENDIF"} <= set(items)
    assert not {"End Loop", "Event", "Loop … End Loop"} & set(items)


async def test_signature_help_writes_the_axes_in_round_brackets(client: LanguageClient) -> None:
    uri = "file:///work/signature.mnt"
    text = "DEFINE xAxis = 0\nLoop\nEnd Loop\nMOVER(\n"
    await open_document(client, uri, text)
    found = await client.text_document_signature_help_async(
        types.SignatureHelpParams(text_document=document(uri), position=position(text, "MOVER(", 6))
    )
    assert found is not None and found.signatures[0].label.startswith("MOVER(axes) = <expression>")


async def test_completion_after_a_keywords_round_bracket_offers_its_axes(client: LanguageClient) -> None:
    uri = "file:///work/axes.mnt"
    text = "DEFINE xAxis = 0\nDEFINE notAxis = 99\nLoop\nEnd Loop\nMOVER(\n"
    await open_document(client, uri, text)
    items = await _labels(client, uri, text, "MOVER(", 6)
    assert {"0", "1", "xAxis"} <= set(items)
    assert items["xAxis"].text_edit.new_text == "xAxis"  # by name in the brackets: MOVER(xAxis)
    assert "SPEED" not in items and "notAxis" not in items and "99" not in items


async def test_a_subroutine_ends_before_the_event_block_after_it(client: LanguageClient) -> None:
    uri = "file:///work/outline.mnt"
    text = (
        "DIM a\nLoop\n  GOSUB sub1\nEnd Loop\n\n"
        "#sub1\n  a = 1\nRETURN\n\n' the host's command\n"
        "Event COMMS1\n  a = 2\nEnd Event\n"
        "Startup\n  a = 3\nEnd Startup\n"
    )
    await open_document(client, uri, text)
    symbols = await client.text_document_document_symbol_async(types.DocumentSymbolParams(text_document=document(uri)))
    outline = [(symbol.name, symbol.kind, symbol.range.start.line, symbol.range.end.line) for symbol in symbols or []]
    # 0-based lines: #sub1 on 5 to its RETURN on 7 (the range ends at the start of line 8), Event 10 to 12,
    # Startup 13 to 15
    assert outline == [
        ("a", types.SymbolKind.Variable, 0, 0),
        ("#sub1", types.SymbolKind.Function, 5, 8),
        ("Event COMMS1", types.SymbolKind.Event, 10, 12),
        ("Startup", types.SymbolKind.Constructor, 13, 15),
    ]
