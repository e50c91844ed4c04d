"""MintMT in the editor, over stdio: ``mint.dialect = auto`` reads each note listing as MintMT, and every
feature (diagnostics, hover, completion, formatting, folding, semantic tokens, symbols) works on it."""

from __future__ import annotations

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import LanguageClient, client_capabilities

from mintlang.keyworddb import database
from mintlang.lsp.features.semantic_tokens import TOKEN_TYPES
from tests.corpus_files import CORPUS, CorpusCase, cases
from tests.lsp.conftest import EDITOR, SHARED, document, open_document, position, uri_of
from tests.lsp.test_formatting import apply
from tests.lsp.test_simulator import shown_output

pytestmark = pytest.mark.asyncio
LISTINGS = cases("mintmt")
SPACES = types.FormattingOptions(tab_size=2, insert_spaces=True)
ERROR = types.DiagnosticSeverity.Error


AUTO = types.InitializeParams(
    capabilities=client_capabilities("visual-studio-code"),
    initialization_options={"mint": {"debounceMs": 0, "dialect": "auto"}},
)


@pytest_lsp.fixture(config=EDITOR)
async def client(lsp_client: LanguageClient):
    await lsp_client.initialize_session(AUTO)
    yield
    await lsp_client.shutdown_session()


@pytest_lsp.fixture(config=EDITOR, scope="module")
async def shared_client(lsp_client: LanguageClient):
    """The conftest's ``shared_client`` with this module's settings."""
    await lsp_client.initialize_session(AUTO)
    yield
    await lsp_client.shutdown_session()


def _listing(name: str) -> tuple[str, str]:
    path = CORPUS / "mintmt" / name
    return uri_of(path), path.read_text(encoding="utf-8")


@SHARED
@pytest.mark.parametrize("case", LISTINGS, ids=lambda case: case.name)
async def test_every_listing_gets_the_errors_the_note_implies_and_formats_stably(
    shared_client: LanguageClient, case: CorpusCase
) -> None:
    uri = uri_of(case.path)
    diagnostics = await open_document(shared_client, uri, case.source)
    errors = {
        (str(diagnostic.code), diagnostic.range.start.line + 1)
        for diagnostic in diagnostics
        if diagnostic.severity is ERROR and not (case.fragment and diagnostic.code == "E3001")
    }
    assert errors == set(case.expected)
    params = types.DocumentFormattingParams(text_document=document(uri), options=SPACES)
    formatted = apply(case.source, await shared_client.text_document_formatting_async(params) or [])
    other = "file:///formatted/" + case.path.name
    await open_document(shared_client, other, formatted)
    again = types.DocumentFormattingParams(text_document=document(other), options=SPACES)
    assert not await shared_client.text_document_formatting_async(again)
    assert [line.strip() for line in formatted.split("\n")] == [line.strip() for line in case.source.split("\n")]


async def test_formatting_indents_loop_if_event_and_startup_blocks_and_keeps_the_case_of_words(
    client: LanguageClient,
) -> None:
    uri = "file:///work/blocks.mnt"
    text = (
        "Startup\nMOVEBUFFERSIZE(0) = 20   \nEnd Startup\n"
        "Loop\n' wait\nIf (COMMS(1) = 1) Then\nGO(0)\nEnd If\nEnd Loop\n"
        "Event Comms1\n    JOG(0) = comms(1)\nEnd Event\n"
    )
    await open_document(client, uri, text)
    params = types.DocumentFormattingParams(text_document=document(uri), options=SPACES)
    assert apply(text, await client.text_document_formatting_async(params) or []) == (
        "Startup\n  MOVEBUFFERSIZE(0) = 20\nEnd Startup\n"
        "Loop\n  ' wait\n  If (COMMS(1) = 1) Then\n    GO(0)\n  End If\nEnd Loop\n"
        "Event Comms1\n  JOG(0) = comms(1)\nEnd Event\n"
    )


async def test_loop_if_event_and_startup_blocks_fold(client: LanguageClient) -> None:
    uri, text = _listing("an00117_l0114_movebufferlow_event.mnt")
    await open_document(client, uri, text)
    ranges = await client.text_document_folding_range_async(types.FoldingRangeParams(text_document=document(uri)))
    # 0-based: Loop on 4 to End Loop on 6, Event 8 to 15, its If 10 to 14, Startup 18 to 22; each closer stays shown;
    # and the four comment lines that open the file
    assert {(fold.start_line, fold.end_line) for fold in ranges or []} == {
        (4, 5),
        (8, 14),
        (10, 13),
        (18, 21),
        (0, 3),
    }


async def test_event_and_startup_blocks_are_symbols(client: LanguageClient) -> None:
    uri, text = _listing("an00117_l0114_movebufferlow_event.mnt")
    await open_document(client, uri, text)
    symbols = await client.text_document_document_symbol_async(types.DocumentSymbolParams(text_document=document(uri)))
    outline = [(symbol.name, symbol.kind, symbol.range.start.line, symbol.range.end.line) for symbol in symbols or []]
    assert outline == [
        ("Event MOVEBUFFERLOW", types.SymbolKind.Event, 8, 15),
        ("Startup", types.SymbolKind.Constructor, 18, 22),
    ]


async def test_mintmt_keywords_are_described_on_hover(client: LanguageClient) -> None:
    uri, text = _listing("an00117_l0059_triggermode.mnt")
    await open_document(client, uri, text)
    hover = await client.text_document_hover_async(
        types.HoverParams(text_document=document(uri), position=position(text, "TRIGGERMODE(0)", 3))
    )
    assert isinstance(hover, types.Hover) and isinstance(hover.contents, types.MarkupContent)
    # the entry written from the move buffer note, which v4's database does not have
    assert database().lookup("TRIGGERMODE") is None
    assert database().mintmt_keywords["TRIGGERMODE"].summary in hover.contents.value


async def test_mintmt_keywords_are_completed(client: LanguageClient) -> None:
    uri = "file:///work/complete.mnt"
    text = "Loop\n  TRIGG\nEnd Loop\n"
    await open_document(client, uri, text)
    answer = await client.text_document_completion_async(
        types.CompletionParams(text_document=document(uri), position=types.Position(line=1, character=7))
    )
    items = answer.items if isinstance(answer, types.CompletionList) else answer or []
    assert "TRIGGERMODE" in {item.label for item in items}


async def test_a_completed_keyword_is_documented_as_mintmt_writes_it(client: LanguageClient) -> None:
    # The move buffer note writes CONTOURMODE(0) (004:181), v4 CONTOURMODE[axes] (000:8544): under auto the
    # item resolved must describe the program's dialect, not the editor's setting
    uri = "file:///work/contour.mnt"
    text = "Loop\n  CONTOURM\nEnd Loop\n"
    await open_document(client, uri, text)
    answer = await client.text_document_completion_async(
        types.CompletionParams(text_document=document(uri), position=types.Position(line=1, character=10))
    )
    items = answer.items if isinstance(answer, types.CompletionList) else answer or []
    offered = next(item for item in items if item.label == "CONTOURMODE")
    resolved = await client.completion_item_resolve_async(offered)
    assert isinstance(resolved.documentation, types.MarkupContent)
    assert "CONTOURMODE(axes) = <expression>" in resolved.documentation.value
    assert "CONTOURMODE[axes]" not in resolved.documentation.value


async def test_block_words_are_keywords_and_quote_comments_comments(client: LanguageClient) -> None:
    uri, text = _listing("an00117_l0114_movebufferlow_event.mnt")
    await open_document(client, uri, text)
    answer = await client.text_document_semantic_tokens_full_async(
        types.SemanticTokensParams(text_document=document(uri))
    )
    assert answer is not None
    lines, coloured, line, column = text.split("\n"), {}, 0, 0
    data = answer.data
    for index in range(0, len(data), 5):
        delta_line, delta_start, length, kind, _ = data[index : index + 5]
        line, column = line + delta_line, (column + delta_start if delta_line == 0 else delta_start)
        coloured[lines[line][column : column + length]] = TOKEN_TYPES[kind]
    for word in ("Loop", "End Loop", "Event", "If", "Then", "EndIf", "End Event", "Startup", "End Startup"):
        assert coloured[word] == "keyword", word
    assert coloured["' Trigger motion"] == "comment"
    assert coloured["MOVEBUFFERLOW"] == "keyword"
    assert "(" not in coloured  # MOVER(0)'s round bracket is punctuation, left uncoloured as any other


async def test_under_auto_a_v4_program_stays_v4(client: LanguageClient) -> None:
    # v4's character constant and dot addressing: read as MintMT, 'A' would start a comment and leave "a =" broken
    text = "DIM a\na = 'A'\nMOVER.0 = a\nGO.0\n"
    assert await open_document(client, "file:///work/v4.mnt", text) == []


async def test_a_mintmt_program_gets_the_run_lens_and_runs_as_mintmt(client: LanguageClient, tmp_path) -> None:
    # Startup runs first (MT-7), the quote is a comment: read as v4 the program would not even compile.
    text = 'Print "main"\nStartup\n  Print "startup" \' first\nEnd Startup\n'
    program = tmp_path / "cell.mnt"
    program.write_text(text, encoding="utf-8")
    assert await open_document(client, uri_of(program), text) == []
    found = await client.text_document_code_lens_async(
        types.CodeLensParams(text_document=types.TextDocumentIdentifier(uri=uri_of(program)))
    )
    assert [lens.command.command for lens in found or [] if lens.command is not None] == ["mint.simulateFile"]
    report = await client.workspace_execute_command_async(
        types.ExecuteCommandParams(command="mint.simulateFile", arguments=[uri_of(program)])
    )
    assert report["stopped"] == "end"
    assert "startup\nmain\n" in shown_output(client)
