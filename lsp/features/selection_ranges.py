"""Selection ranges ("expand selection"): from the word at the cursor outwards, as Mint nests.

A word, then each expression around it, the statement, the logical line (a
DIM list continued over lines is one), each block that encloses the line (its
opener to its closer), the labelled part it is in (the main program or a
subroutine, to its last written line, as in the outline), and the whole file.
Equal ranges are given once, so every step grows the selection.
"""

from __future__ import annotations

from lsprotocol import types

from mintlang.diagnostics import Span
from mintlang.lsp.addressed import placed_line
from mintlang.lsp.features.call_hierarchy import parts
from mintlang.lsp.lookup import token_at
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Snapshot
from mintlang.syntax import nodes as n


def _within_line(line: n.PlacedLine, offset: int) -> list[Span]:
    """The statements and expressions of ``line`` around ``offset``, innermost first."""
    found: list[Span] = []
    for statement in n.walk_statements(line.syntax.statements):
        span = line.span(statement.span)
        if not span.start <= offset <= span.end:
            continue
        found.append(span)
        for expression in n.expressions_of(statement):
            for node in n.walk_expression(expression):
                inner = line.span(node.span)
                if inner.start <= offset <= inner.end:
                    found.append(inner)
    return sorted(found, key=lambda span: span.end - span.start)


def _line_content(snapshot: Snapshot, line: n.PlacedLine) -> Span:
    """The logical line from its first character that is no blank to the end of its last physical line."""
    source = snapshot.document.source
    start = line.origin + len(source[line.origin :]) - len(source[line.origin :].lstrip(" \t"))
    last = snapshot.positions.position(line.span(line.syntax.span).end).line
    return Span(min(start, _line_end(snapshot, last)), _line_end(snapshot, last))


def _blocks(snapshot: Snapshot, number: int) -> list[Span]:
    """The blocks that enclose the 1-based line ``number``, innermost first, as whole lines."""
    positions = snapshot.positions
    found = []
    for block in snapshot.model.structures[snapshot.unit].blocks:
        last = block.closer.line if block.closer is not None else positions.line_count
        if block.opener.line <= number <= last:
            start = positions.line_start(block.opener.line - 1)
            end = _line_end(snapshot, last - 1)
            found.append(Span(start, end))
    return sorted(found, key=lambda span: span.end - span.start)


def _line_end(snapshot: Snapshot, line: int) -> int:
    """Where the 0-based ``line`` ends, before its line break."""
    source, positions = snapshot.document.source, snapshot.positions
    end = positions.line_start(line + 1) if line + 1 < positions.line_count else len(source)
    return len(source[:end].rstrip("\r\n")) if end > positions.line_start(line) else end


def spans(snapshot: Snapshot, offset: int) -> list[Span]:
    """Every range around ``offset``, innermost first, each containing the one before and larger than it."""
    found: list[Span] = []
    word = token_at(snapshot.document, offset)
    if word is not None:
        found.append(Span(word.start, word.end))
    line = placed_line(snapshot, snapshot.unit, offset)
    if line is not None:
        found += _within_line(line, offset)
        found.append(_line_content(snapshot, line))
        found += _blocks(snapshot, line.number)
    found += [Span(part.start, part.written) for part in parts(snapshot) if part.start <= offset <= part.written]
    found.append(Span(0, len(snapshot.document.source)))
    nested: list[Span] = []
    for span in found:
        if not nested or (span.start <= nested[-1].start and nested[-1].end <= span.end and span != nested[-1]):
            nested.append(span)
    return nested


def selection_range(snapshot: Snapshot, position: types.Position) -> types.SelectionRange:
    chain: types.SelectionRange | None = None
    for span in reversed(spans(snapshot, snapshot.positions.offset(position))):
        chain = types.SelectionRange(range=snapshot.positions.range(span), parent=chain)
    assert chain is not None  # the whole file is always there
    return chain


def register(server: MintServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_SELECTION_RANGE)
    def selection_ranges(params: types.SelectionRangeParams) -> list[types.SelectionRange] | None:
        snapshot = server.snapshot(params.text_document.uri)
        if snapshot is None:
            return None
        return [selection_range(snapshot, position) for position in params.positions]
