"""The language server object: shared state and the registration of every feature.

One ``MintServer`` holds the open documents (pygls' workspace) and their
analyses; each module of ``features`` registers the handlers of one LSP
feature on it. pygls answers any exception raised in a request handler with
an error response and logs it, so no handler can stop the server.
"""

from __future__ import annotations

import asyncio
import logging
from collections.abc import Awaitable, Callable, Collection
from pathlib import Path
from typing import Any
from urllib.parse import unquote

from lsprotocol import types
from pygls.exceptions import JsonRpcException
from pygls.lsp.server import LanguageServer
from pygls.uris import to_fs_path
from pygls.workspace import TextDocument

from mintlang import __version__
from mintlang.lsp.collector import Collector
from mintlang.lsp.disk import read_text
from mintlang.lsp.lookup import line_prefix
from mintlang.lsp.positions import Positions
from mintlang.lsp.protocol import (
    UNREADABLE,
    DecodeErrorsInOneLine,
    MintProtocol,
    ParseErrorsInOneLine,
    RefusalsInOneLine,
)
from mintlang.lsp.workspace import MAX_CHARACTERS, Analyses, Snapshot

log = logging.getLogger(__name__)


class MintServer(LanguageServer):
    def __init__(self) -> None:
        super().__init__("mint-lsp", __version__, protocol_cls=MintProtocol)  # LSP line ends, every request answered
        logging.getLogger("pygls.server").addFilter(ParseErrorsInOneLine())  # its message loop logs them
        logging.getLogger("pygls.protocol.json_rpc").addFilter(DecodeErrorsInOneLine())  # and its decoder these
        logging.getLogger("pygls.protocol.json_rpc").addFilter(RefusalsInOneLine())  # and its handlers' refusals
        self.analyses = Analyses(read=self.read_text, opened=self.opened, collector=Collector())
        self.when_initialized: list[Callable[[], Awaitable[None]]] = []  # features' work once the client is ready
        self.when_settings_changed: list[Callable[[], Awaitable[None]]] = []  # and once the settings changed
        self.settings_pull: asyncio.Future[None] | None = None  # the editor's settings being asked for, if they are

    def report_server_error(self, error: Exception, source: Any) -> None:
        """A body the message loop (``source``) cannot read is answered with ``ParseError``; anything else is
        pygls' to show."""
        if source is JsonRpcException and isinstance(error, UNREADABLE) and isinstance(self.protocol, MintProtocol):
            self.protocol.refuse_unreadable(error)
            return
        super().report_server_error(error, source)

    def opened(self) -> Collection[str]:
        """The URIs of the documents open in the editor, as the editor writes them."""
        return dict.fromkeys(document.uri for document in self.workspace.text_documents.values()).keys()

    def document(self, uri: str) -> TextDocument | None:
        """The editor's copy of the document ``uri`` names, None when it is not open. pygls keeps them by the
        unescaped URI; the editor's is escaped (``Press%201``, and ``file:///c%3A/`` from VS Code on Windows)."""
        return self.workspace.text_documents.get(unquote(uri))

    def read_text(self, uri: str) -> str | None:
        """The text of an open document, else of the file on disk; None when there is none."""
        document = self.document(uri)
        if document is not None:
            return document.source
        path = to_fs_path(uri)
        return read_text(Path(path), 4 * MAX_CHARACTERS) if path is not None else None

    def snapshot(self, uri: str) -> Snapshot | None:
        """The analysis of an open document; None for documents the client never opened."""
        document = self.document(uri)
        if document is None:
            return None
        return self.analyses.snapshot(uri, document.source, document.version)

    def typing(self, uri: str, position: types.Position) -> tuple[Snapshot, str] | None:
        """The last analysis of a document (maybe a few keystrokes old) and its current line up to
        ``position``: enough for completion and signature help, which must not wait for a new check."""
        document = self.document(uri)
        if document is None:
            return None
        snapshot = self.analyses.latest(uri) or self.analyses.snapshot(uri, document.source, document.version)
        if snapshot.skipped is None and snapshot.document.source == document.source:
            positions = snapshot.positions  # the text analysed is the text typed: its lines are known already
        else:
            positions = Positions(document.source, self.analyses.encoding)
        return snapshot, line_prefix(positions, document.source, position)


def create_server() -> MintServer:
    from mintlang.lsp.features import FEATURES  # noqa: PLC0415  (features import MintServer)

    server = MintServer()
    for feature in FEATURES:
        feature.register(server)
    return server
