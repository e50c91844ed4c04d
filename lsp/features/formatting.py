"""Formatting: keywords in upper case and block bodies indented; nothing else changes.

Comments (but for their REM), strings, user names and the spacing inside
lines are left byte for byte; a macro's text is Mint too, so its keywords are
upper-cased like any others. Indentation follows the core's block matching: the lines
between an opener and its closer go one level deeper, ELSE sits with its IF,
labels stay at the margin, and continuation lines of a DIM list keep theirs.
"""

from __future__ import annotations

from lsprotocol import types

from mintlang.diagnostics import Span
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Snapshot
from mintlang.syntax.tokens import GRAMMAR_KEYWORDS, TokenKind

_UPPER_CASED = GRAMMAR_KEYWORDS | {TokenKind.KEYWORD, TokenKind.FUNCTION}
_REM = len("REM")  # a comment token starts with its keyword


def _depths(snapshot: Snapshot) -> list[int]:
    """Block depth of every 0-based line."""
    positions = snapshot.positions
    count = positions.line_count
    change = [0] * (count + 1)
    for block in snapshot.model.structures[snapshot.unit].blocks:
        first = block.opener.line  # 0-based line after the opener
        last = block.closer.line - 1 if block.closer is not None else count  # 0-based closer, excluded
        if first < last:
            change[first] += 1
            change[last] -= 1
        if block.middle is not None:
            middle = block.middle.line - 1
            change[middle] -= 1
            change[middle + 1] += 1
    depths, depth = [], 0
    for delta in change[:count]:
        depth += delta
        depths.append(max(0, depth))
    return depths


def _fixed_lines(snapshot: Snapshot) -> set[int]:
    """Lines whose indentation is not the formatter's: labels and continuations of logical lines."""
    positions = snapshot.positions
    fixed: set[int] = set()
    for line in snapshot.document.placed:
        first, syntax = line.number - 1, line.syntax
        fixed.update(range(first + 1, positions.position(line.span(syntax.span).end).line + 1))
        if syntax.label is not None and positions.position(line.span(syntax.label.span).start).line == first:
            fixed.add(first)
    return fixed


def _indentations(snapshot: Snapshot, options: types.FormattingOptions, lines: range) -> dict[int, tuple[int, str]]:
    """Per 0-based line: the offset where its content starts and the indentation it should have."""
    unit = " " * options.tab_size if options.insert_spaces else "\t"
    source, positions = snapshot.document.source, snapshot.positions
    depths, fixed = _depths(snapshot), _fixed_lines(snapshot)
    wanted: dict[int, tuple[int, str]] = {}
    for line in lines:
        start = positions.line_start(line)
        end = start
        while end < len(source) and source[end] in " \t":
            end += 1
        if line not in fixed and end < len(source) and source[end] not in "\r\n":  # blank lines keep theirs
            wanted[line] = (end, unit * depths[line])
    return wanted


def _keywords(snapshot: Snapshot, lines: range) -> dict[int, list[Span]]:
    """Per 0-based line: the spans of its keywords not written in upper case (a comment's REM included)."""
    positions = snapshot.positions
    found: dict[int, list[Span]] = {}
    for token in snapshot.document.tokens:
        if token.kind in _UPPER_CASED:
            span = Span(token.start, token.end)
        elif token.kind is TokenKind.COMMENT:
            span = Span(token.start, token.start + _REM)
        else:
            continue
        text = snapshot.document.source[span.start : span.end]
        if text != text.upper():
            line = positions.position(token.start).line
            if line in lines:
                found.setdefault(line, []).append(span)
    return found


def format_lines(snapshot: Snapshot, options: types.FormattingOptions, lines: range) -> list[types.TextEdit]:
    """One edit per changed line, from its start to its last change, so edits never overlap."""
    if snapshot.skipped is not None:
        return []
    source, positions = snapshot.document.source, snapshot.positions
    indentations, keywords = _indentations(snapshot, options, lines), _keywords(snapshot, lines)
    edits = []
    for line in sorted(indentations.keys() | keywords.keys()):
        start = positions.line_start(line)
        cursor, pieces = (indentations[line][0], [indentations[line][1]]) if line in indentations else (start, [])
        spans = keywords.get(line, [])
        end = max([cursor, *(span.end for span in spans)])
        for span in spans:
            pieces += [source[cursor : span.start], source[span.start : span.end].upper()]
            cursor = span.end
        pieces.append(source[cursor:end])
        new_text = "".join(pieces)
        if new_text != source[start:end]:
            edits.append(types.TextEdit(range=positions.range(Span(start, end)), new_text=new_text))
    return edits


def register(server: MintServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_FORMATTING)
    def whole(params: types.DocumentFormattingParams) -> list[types.TextEdit]:
        snapshot = server.snapshot(params.text_document.uri)
        if snapshot is None:
            return []
        return format_lines(snapshot, params.options, range(snapshot.positions.line_count))

    @server.feature(types.TEXT_DOCUMENT_RANGE_FORMATTING)
    def part(params: types.DocumentRangeFormattingParams) -> list[types.TextEdit]:
        snapshot = server.snapshot(params.text_document.uri)
        if snapshot is None:
            return []
        start, end = params.range.start, params.range.end
        last = end.line - 1 if end.character == 0 and end.line > start.line else end.line  # whole lines selected
        count = snapshot.positions.line_count  # some clients send "everything" as a range past the end
        return format_lines(snapshot, params.options, range(min(start.line, count), min(last + 1, count)))
