"""Inlay hints: the full name after an abbreviated keyword, the text after a macro use.

Each hint reads "≡ what it stands for" (``sp ≡ SPEED.0 = fast ≡ 100 * 2``): no
Mint operator is ``≡``, so a hint cannot be taken for code the way
``SCALE[xAxis = 0, …]`` or ``sp(SPEED)`` could (an assignment, a call).
"""

from __future__ import annotations

from collections.abc import Iterator

from lsprotocol import types

from mintlang.diagnostics import Span
from mintlang.lsp.describe import macro_body
from mintlang.lsp.lookup import abbreviated, token_index
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Snapshot

_STANDS_FOR = "≡ "


def _hint(snapshot: Snapshot, offset: int, meaning: str, tooltip: str) -> types.InlayHint:
    return types.InlayHint(
        position=snapshot.positions.position(offset),
        label=_STANDS_FOR + meaning,
        padding_left=True,
        padding_right=True,
        tooltip=tooltip,
    )


def hints(snapshot: Snapshot, span: Span) -> Iterator[types.InlayHint]:
    document = snapshot.document
    words = snapshot.settings.words
    tokens = document.tokens_in(span.start, span.end)
    for index in range(max(0, token_index(tokens, span.start)), len(tokens)):
        token = tokens[index]
        if token.start > span.end:
            break
        name = abbreviated(token, words)
        if name is not None:
            short = "short for" if not token.text.isalnum() else "the abbreviation of"
            yield _hint(snapshot, token.end, name, f"{token.text} is {short} {name}")
    for expansion in document.expansions:
        if span.start <= expansion.span.start <= span.end:
            body = macro_body(snapshot, expansion.macro)
            if body is not None:
                written = document.source[expansion.span.start : expansion.span.end]
                yield _hint(snapshot, expansion.span.end, body, f"macro {written}: DEFINE {written} = {body}")


def register(server: MintServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_INLAY_HINT)
    def inlay(params: types.InlayHintParams) -> list[types.InlayHint]:
        snapshot = server.snapshot(params.text_document.uri)
        if snapshot is None or snapshot.skipped is not None:
            return []
        return sorted(
            hints(snapshot, snapshot.positions.span(params.range)),
            key=lambda hint: (hint.position.line, hint.position.character),
        )
