"""Diagnostics, pulled by clients that can, pushed to the others (debounced while typing, both ways).

Never both: a client that pulls keeps pulled and pushed diagnostics in separate
collections, so VS Code would list every problem twice. Codes are the
controller's error numbers (``E3001``) and the toolchain's own (``W103``); the
core's messages already start with the manual's title.
"""

from __future__ import annotations

import asyncio
import logging
import math
import time
from collections.abc import Iterable

from lsprotocol import types

import mintlang
from mintlang.codes import OWN_CODES
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Snapshot, partner
from mintlang.ruledocs.links import configured_base, rule_url

log = logging.getLogger(__name__)
_SEVERITY = {
    mintlang.Severity.ERROR: types.DiagnosticSeverity.Error,
    mintlang.Severity.WARNING: types.DiagnosticSeverity.Warning,
    mintlang.Severity.INFO: types.DiagnosticSeverity.Information,
}
_UNNECESSARY = frozenset({"W103", "W104", "W105", "W106"})  # unused or unreachable: clients grey it out


def to_lsp(diagnostic: mintlang.Diagnostic, snapshot: Snapshot) -> types.Diagnostic:
    message = _titled(diagnostic.code, diagnostic.message)
    return types.Diagnostic(
        range=snapshot.positions.range(diagnostic.span),
        message=message,
        severity=_SEVERITY[diagnostic.severity],
        code=diagnostic.code,
        source="mint",
        tags=[types.DiagnosticTag.Unnecessary] if diagnostic.code in _UNNECESSARY else None,
        code_description=_page(diagnostic.code, snapshot.settings.rules_url),
    )


def _titled(code: str, message: str) -> str:
    """The message led by the toolchain's title of its code, once: a message that already opens with the
    title in another letter case (W101's 'typographic quotes: ...') has it capitalised, not repeated."""
    title = OWN_CODES.get(code)
    if title is None:
        return message
    if message.casefold().startswith(title.casefold()):
        return title + message[len(title) :]
    return f"{title}: {message}"


def _page(code: str, base: str | None) -> types.CodeDescription | None:
    """The link to the code's page (``mint.rulesUrl``, else as for the command line), shown on the code."""
    url = rule_url(code, base or configured_base())
    return types.CodeDescription(href=url) if url is not None else None


def lsp_diagnostics(snapshot: Snapshot) -> list[types.Diagnostic]:
    if snapshot.skipped is not None:
        start = types.Position(line=0, character=0)
        return [
            types.Diagnostic(
                range=types.Range(start=start, end=start),
                message=snapshot.skipped,
                severity=types.DiagnosticSeverity.Information,
                source="mint",
            )
        ]
    return [to_lsp(diagnostic, snapshot) for diagnostic in snapshot.diagnostics]


def _pulls(server: MintServer) -> bool:
    text_document = server.client_capabilities.text_document
    return text_document is not None and text_document.diagnostic is not None


def _refresh_pulled(server: MintServer) -> None:
    """Ask a pulling client to pull again: what it holds for other documents may be out of date."""
    workspace = server.client_capabilities.workspace
    if workspace is not None and workspace.diagnostics is not None and workspace.diagnostics.refresh_support:
        server.workspace_diagnostic_refresh(None)


def refresh_all(server: MintServer) -> None:
    """Settings changed: every open document's diagnostics may have."""
    if _pulls(server):
        _refresh_pulled(server)
        return
    for uri in list(server.opened()):
        publish(server, uri)


def recheck(server: MintServer, uris: Iterable[str]) -> None:
    """Files these documents read changed on disk: their diagnostics may have."""
    uris = list(uris)
    if uris and _pulls(server):
        _refresh_pulled(server)
    elif uris:
        for uri in uris:
            publish(server, uri)


def publish(server: MintServer, uri: str) -> None:
    start = time.perf_counter()
    snapshot = server.snapshot(uri)
    if snapshot is not None:
        log.debug("diagnostics of %s v%s in %.1f ms", uri, snapshot.version, (time.perf_counter() - start) * 1000)
        server.text_document_publish_diagnostics(
            types.PublishDiagnosticsParams(uri=uri, version=snapshot.version, diagnostics=lsp_diagnostics(snapshot))
        )


class _Debouncer:
    """Publishes a document's diagnostics once typing pauses for ``debounce_ms``, and holds a pull of them till then:
    a client that pulls at each change (VS Code) would otherwise see every keystroke's check."""

    def __init__(self, server: MintServer) -> None:
        self.server = server
        self.pending: dict[str, asyncio.Task[None]] = {}
        self.typed: dict[str, float] = {}  # when each document being typed in last changed (the loop's clock)

    async def paused(self, uri: str) -> None:
        """Once typing in ``uri`` has paused for ``debounce_ms``; at once for a document not typed in since."""
        loop = asyncio.get_running_loop()
        while (wait := self.typed.get(uri, -math.inf) + self._delay() - loop.time()) > 0:
            await asyncio.sleep(wait)

    def _delay(self) -> float:
        return self.server.analyses.settings.debounce_ms / 1000

    def now(self, uri: str) -> None:
        self.cancel(uri)
        if not _pulls(self.server):  # a pulling client asks for this document's own
            publish(self.server, uri)
        self.partner(uri)

    def later(self, uri: str) -> None:
        self.cancel(uri)
        delay = self._delay()
        self.typed[uri] = asyncio.get_running_loop().time()
        if delay <= 0:
            self.now(uri)
        else:
            self.pending[uri] = asyncio.get_running_loop().create_task(self._after(uri, delay))

    def cancel(self, uri: str) -> None:
        self.typed.pop(uri, None)
        task = self.pending.pop(uri, None)
        if task is not None:
            task.cancel()

    def partner(self, uri: str) -> None:
        """The other file of the application is analysed with this one: refresh it too."""
        _, other = partner(uri, self.server.analyses.settings_for(uri), self.server.opened())
        if other is None or other not in self.server.opened():
            return
        if _pulls(self.server):
            _refresh_pulled(self.server)
        else:
            publish(self.server, other)

    async def _after(self, uri: str, delay: float) -> None:
        await asyncio.sleep(delay)
        self.pending.pop(uri, None)
        try:
            self.now(uri)
        except Exception:  # a task of our own: nobody else would see the failure
            log.exception("diagnostics of %s failed", uri)


def register(server: MintServer) -> None:
    debouncer = _Debouncer(server)

    @server.feature(types.TEXT_DOCUMENT_DID_OPEN)
    def did_open(params: types.DidOpenTextDocumentParams) -> None:
        debouncer.now(params.text_document.uri)

    @server.feature(types.TEXT_DOCUMENT_DID_CHANGE)
    async def did_change(params: types.DidChangeTextDocumentParams) -> None:
        debouncer.later(params.text_document.uri)

    @server.feature(types.TEXT_DOCUMENT_DID_SAVE)
    def did_save(params: types.DidSaveTextDocumentParams) -> None:
        debouncer.now(params.text_document.uri)

    @server.feature(types.TEXT_DOCUMENT_DID_CLOSE)
    def did_close(params: types.DidCloseTextDocumentParams) -> None:
        uri = params.text_document.uri
        debouncer.cancel(uri)
        server.analyses.forget(uri)
        if not _pulls(server):
            server.text_document_publish_diagnostics(types.PublishDiagnosticsParams(uri=uri, diagnostics=[]))
        debouncer.partner(uri)

    @server.feature(
        types.TEXT_DOCUMENT_DIAGNOSTIC,
        types.DiagnosticOptions(identifier="mint", inter_file_dependencies=True, workspace_diagnostics=False),
    )
    async def pull(params: types.DocumentDiagnosticParams) -> types.RelatedFullDocumentDiagnosticReport:
        await debouncer.paused(params.text_document.uri)
        snapshot = server.snapshot(params.text_document.uri)
        items = lsp_diagnostics(snapshot) if snapshot is not None else []
        return types.RelatedFullDocumentDiagnosticReport(items=items)
