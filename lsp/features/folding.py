"""Folding ranges: matched blocks (an IF's two branches apart), labelled subroutines, and runs of comment
lines (a program's opening remarks, the notes above a subroutine)."""

from __future__ import annotations

from collections.abc import Iterator

from lsprotocol import types

from mintlang.lsp.features.symbols import sections
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Snapshot


def _fold(first: int, last: int) -> Iterator[types.FoldingRange]:
    """Lines ``first`` .. ``last`` (0-based), the first staying visible; nothing for one line."""
    if last > first:
        yield types.FoldingRange(start_line=first, end_line=last, kind=types.FoldingRangeKind.Region)


def _comment_runs(snapshot: Snapshot) -> Iterator[types.FoldingRange]:
    """Two or more consecutive lines holding only a comment (REM, or MintMT's ``'``), as comment ranges."""
    first = None
    for number, (_, line) in enumerate([*snapshot.document.physical, (0, None)]):
        comment_only = line is not None and not line.kinds and line.comment_start >= 0
        if comment_only and first is None:
            first = number
        elif not comment_only and first is not None:
            if number - 1 > first:
                yield types.FoldingRange(start_line=first, end_line=number - 1, kind=types.FoldingRangeKind.Comment)
            first = None


def folding_ranges(snapshot: Snapshot) -> Iterator[types.FoldingRange]:
    for block in snapshot.model.structures[snapshot.unit].blocks:
        if block.closer is None:
            continue
        opener, closer = block.opener.line - 1, block.closer.line - 1
        if block.middle is not None:
            middle = block.middle.line - 1
            yield from _fold(opener, middle - 1)
            yield from _fold(middle, closer - 1)
        else:
            yield from _fold(opener, closer - 1)
    for section in sections(snapshot):
        yield from _fold(section.first_line, section.last_line)
    yield from _comment_runs(snapshot)


def register(server: MintServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_FOLDING_RANGE)
    def folding(params: types.FoldingRangeParams) -> list[types.FoldingRange]:
        snapshot = server.snapshot(params.text_document.uri)
        return list(folding_ranges(snapshot)) if snapshot is not None else []
