"""Every request on every corpus program (v4, v3, MintMT, configuration files, broken ones), at the start,
indentation, middle and end of every line, is answered without an internal error.

The handlers are called in-process through pygls' feature table, so the sweep
over some 600 files takes seconds; the other tests of this folder cover the
same handlers over real stdio. A ``JsonRpcException`` is a deliberate error
answer (a refused rename) and allowed.
"""

from __future__ import annotations

import asyncio
import contextlib
import inspect
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from lsprotocol import types as t
from pygls.exceptions import JsonRpcException

from mintlang.allocation import thaw_held
from mintlang.dialect import Dialect
from mintlang.lsp.server import MintServer, create_server
from mintlang.lsp.workspace import Settings

CORPUS = Path(__file__).parents[1] / "corpus"
PROGRAMS = sorted(path for path in CORPUS.rglob("*") if path.suffix in (".mnt", ".cfg"))
DIALECT_OF = {"v3": Dialect.V3, "mintmt": Dialect.MINTMT}  # by the corpus folder; v4 otherwise
FORMAT = t.FormattingOptions(tab_size=2, insert_spaces=True)


@pytest.fixture(scope="module")
def server() -> Iterator[MintServer]:
    server = create_server()
    # A client that confirms annotated edits: a rename merging two spellings would otherwise ask this
    # client, which has no one to answer, a question (test_rename covers the question).
    edits = t.WorkspaceEditClientCapabilities(
        document_changes=True, change_annotation_support=t.ChangeAnnotationsSupportOptions()
    )
    capabilities = t.ClientCapabilities(workspace=t.WorkspaceClientCapabilities(workspace_edit=edits))
    for _ in server.protocol.lsp_initialize(t.InitializeParams(capabilities=capabilities)):
        pass  # no initialize handler of ours needs to run
    yield server
    thaw_held()  # each analysis was frozen, and with no event loop here no idle collection thaws them


@pytest.fixture(scope="module")
def loop() -> Iterator[asyncio.AbstractEventLoop]:
    """One event loop for the whole sweep's asynchronous handler (rename): a loop made for each
    rename, at every position of every line, cost more than the rename."""
    loop = asyncio.new_event_loop()
    yield loop
    loop.close()


def _caller(server: MintServer, loop: asyncio.AbstractEventLoop) -> Callable[[str, object], object]:
    features = server.protocol.fm.features

    def call(method: str, params: object) -> object:
        answer = features[method](params)
        return loop.run_until_complete(answer) if inspect.isawaitable(answer) else answer

    return call


def _document_requests(call: Callable[[str, object], object], doc: t.TextDocumentIdentifier, lines: int) -> None:
    whole = t.Range(start=t.Position(0, 0), end=t.Position(lines, 0))
    call(t.TEXT_DOCUMENT_DIAGNOSTIC, t.DocumentDiagnosticParams(text_document=doc))
    call(t.TEXT_DOCUMENT_DOCUMENT_SYMBOL, t.DocumentSymbolParams(text_document=doc))
    call(t.TEXT_DOCUMENT_FOLDING_RANGE, t.FoldingRangeParams(text_document=doc))
    call(t.TEXT_DOCUMENT_SEMANTIC_TOKENS_FULL, t.SemanticTokensParams(text_document=doc))
    call(t.TEXT_DOCUMENT_FORMATTING, t.DocumentFormattingParams(text_document=doc, options=FORMAT))
    call(t.TEXT_DOCUMENT_INLAY_HINT, t.InlayHintParams(text_document=doc, range=whole))
    for lens in call(t.TEXT_DOCUMENT_CODE_LENS, t.CodeLensParams(text_document=doc)) or []:  # type: ignore[union-attr]
        call(t.CODE_LENS_RESOLVE, lens)
    context = t.CodeActionContext(diagnostics=[])
    for action in call(t.TEXT_DOCUMENT_CODE_ACTION, t.CodeActionParams(doc, whole, context)) or []:  # type: ignore[union-attr]
        if action.data is not None:
            call(t.CODE_ACTION_RESOLVE, action)


def _position_requests(call: Callable[[str, object], object], doc: t.TextDocumentIdentifier, at: t.Position) -> None:
    completion = call(t.TEXT_DOCUMENT_COMPLETION, t.CompletionParams(text_document=doc, position=at))
    for item in list(getattr(completion, "items", completion) or [])[:3]:
        call(t.COMPLETION_ITEM_RESOLVE, item)
    call(t.TEXT_DOCUMENT_HOVER, t.HoverParams(text_document=doc, position=at))
    call(t.TEXT_DOCUMENT_SIGNATURE_HELP, t.SignatureHelpParams(text_document=doc, position=at))
    call(t.TEXT_DOCUMENT_DEFINITION, t.DefinitionParams(text_document=doc, position=at))
    context = t.ReferenceContext(include_declaration=True)
    call(t.TEXT_DOCUMENT_REFERENCES, t.ReferenceParams(text_document=doc, position=at, context=context))
    call(t.TEXT_DOCUMENT_DOCUMENT_HIGHLIGHT, t.DocumentHighlightParams(text_document=doc, position=at))
    call(t.TEXT_DOCUMENT_DECLARATION, t.DeclarationParams(text_document=doc, position=at))
    call(t.TEXT_DOCUMENT_LINKED_EDITING_RANGE, t.LinkedEditingRangeParams(text_document=doc, position=at))
    call(t.TEXT_DOCUMENT_SELECTION_RANGE, t.SelectionRangeParams(text_document=doc, positions=[at]))
    prepared = call(
        t.TEXT_DOCUMENT_PREPARE_CALL_HIERARCHY, t.CallHierarchyPrepareParams(text_document=doc, position=at)
    )
    for item in prepared or []:  # type: ignore[union-attr]
        call(t.CALL_HIERARCHY_INCOMING_CALLS, t.CallHierarchyIncomingCallsParams(item=item))
        call(t.CALL_HIERARCHY_OUTGOING_CALLS, t.CallHierarchyOutgoingCallsParams(item=item))
    with contextlib.suppress(JsonRpcException):
        call(t.TEXT_DOCUMENT_PREPARE_RENAME, t.PrepareRenameParams(text_document=doc, position=at))
    with contextlib.suppress(JsonRpcException):
        call(t.TEXT_DOCUMENT_RENAME, t.RenameParams(text_document=doc, position=at, new_name="zz"))


@pytest.mark.parametrize("path", PROGRAMS, ids=lambda path: str(path.relative_to(CORPUS)))
def test_every_request_is_answered(server, loop, path):
    text = path.read_text(encoding="utf-8", errors="replace")
    dialect = next((DIALECT_OF[part] for part in path.relative_to(CORPUS).parts if part in DIALECT_OF), Dialect.V4)
    server.analyses.settings = Settings.from_options({"dialect": dialect.value})  # given: over any settings file
    uri = path.resolve().as_uri()
    server.workspace.put_text_document(t.TextDocumentItem(uri=uri, language_id="mint", version=1, text=text))
    doc = t.TextDocumentIdentifier(uri=uri)
    call = _caller(server, loop)
    lines = text.splitlines() or [""]
    _document_requests(call, doc, len(lines))
    for number, line in enumerate(lines):
        indentation = len(line) - len(line.lstrip())
        for character in sorted({0, indentation, len(line) // 2, len(line)}):
            _position_requests(call, doc, t.Position(number, character))
        one_line = t.Range(start=t.Position(number, 0), end=t.Position(number + 1, 0))
        call(t.TEXT_DOCUMENT_RANGE_FORMATTING, t.DocumentRangeFormattingParams(doc, one_line, FORMAT))
    server.workspace.remove_text_document(uri)
