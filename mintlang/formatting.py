"""Formatting Mint, the house style: upper-case keywords, labels at the margin, blocks indented, no trailing blanks.

* Keywords (a comment's REM included, and those in a macro's text, which is Mint
  too) are written in upper case, in v3 and v4; a label named like a keyword
  (``GOSUB home``) is a user name and keeps its case. MintMT keeps every word as
  written: its notes write ``Loop``, ``End If``, ``Event`` in mixed case, as
  its programs do, and ``'`` starts most of its comments.
* A label line starts at column 0, wherever it stands: a label names a place in
  the program, not a step of a block.
* Every other line is indented one unit (a tab or some spaces) per block
  that encloses it, by the core's block matching: the lines between an opener
  and its closer go one level deeper and ELSE sits with its IF. A subroutine's
  body is not a block and stays at the margin under its label, as in the
  manual's examples.
* Spaces and tabs at the end of a line go; a line of blanks becomes empty.
* A line the indentation would take past what the controller reads (W111) keeps its own indentation.
* Mint v3's ``PROTECT`` keeps its case: only an upper-case one makes the rest of its line a password, the
  controller ignores any other spelling (001:11089, 001:11091).
* Everything else is left byte for byte: comments but for their REM, strings,
  user names, the spacing inside a line, line ends, and the continuation lines
  of a DIM list, which keep their indentation.

Formatting twice gives what formatting once gives, and a formatted program parses
to what it parsed to, whitespace and letter case aside. ``mint format`` and the
language server's formatting both take their edits from here, and both leave a text
with a syntax error as it is (``first_syntax_error``), as ruff's formatter does: what
the compiler cannot read may be words meant as text (a C comment's), not keywords.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from mintlang.codes import SYNTAX_ERRORS
from mintlang.diagnostics import Diagnostic, Edit, Span, with_edits
from mintlang.dialect import Dialect
from mintlang.semantic.units import Unit
from mintlang.syntax.tokens import GRAMMAR_KEYWORDS, TokenKind

if TYPE_CHECKING:  # the parser and the model are imported by format_text: mint format --help needs neither
    from mintlang.semantic.model import SemanticModel
    from mintlang.syntax.parser import Document

INDENT_WIDTH = 2  # spaces a level unless a project or the command line says otherwise, as the manual indents
INDENT_STYLES = ("space", "tab")
_UPPER_CASED = GRAMMAR_KEYWORDS | {TokenKind.KEYWORD, TokenKind.FUNCTION}
_JUMPS = frozenset({TokenKind.GOSUB, TokenKind.GOTO})  # the word after one is a label, however it is spelt
_REM = len("REM")  # a comment token starts with its keyword
_V3_PROTECT = "PROTECT"  # its case is read: upper case protects the program, any other is ignored (001:11089)


def indent_unit(style: str, width: int) -> str:
    """One level's indentation: a tab, or ``width`` spaces."""
    return "\t" if style == "tab" else " " * width


def project_indent_unit(table: Mapping[str, object]) -> str | None:
    """The indentation a settings file's ``[format]`` table sets, as ``mint format`` reads it (the other key at its
    default); None where it sets neither, or not as the command line takes them."""
    width, style = table.get("indent-width", INDENT_WIDTH), table.get("indent-style", "space")
    if "indent-width" not in table and "indent-style" not in table:
        return None
    if not (isinstance(width, int) and not isinstance(width, bool) and 1 <= width <= 16) or style not in INDENT_STYLES:
        return None
    return indent_unit(str(style), width)


def line_count(document: Document) -> int:
    """How many lines the text has, an empty one after its last line break included."""
    return document.line_index.position(len(document.source)).line


def formatting_edits(model: SemanticModel, unit: Unit, indentation: str, lines: range | None = None) -> list[Edit]:
    """One edit per changed line of ``unit``'s text among 0-based ``lines`` (all by default), from its first to
    its last change, so edits never overlap; ``indentation`` is one level's (a tab, or spaces)."""
    from mintlang.analysis.rules.line_length import longest_line  # noqa: PLC0415 - the rules: see the imports

    document = model.document(unit)
    lines = range(line_count(document)) if lines is None else lines
    source, index = document.source, document.line_index
    indentations = _indentations(model, unit, indentation, lines)
    keywords = _keywords(document, lines)
    limit = longest_line(model.controller, document.dialect)
    edits = []
    for line in lines:
        start = index.line_start(line + 1)
        end = _content_end(source, start)
        old = source[start:end]
        new = _formatted(source, start, end, indentations.get(line), keywords.get(line, []))
        if len(new) > max(limit, len(old)):  # the controller would not read it whole: its own indentation
            new = _formatted(source, start, end, None, keywords.get(line, []))
        if new != old:
            head, tail = _shared(old, new)
            edits.append(Edit(Span(start + head, end - tail), new[head : len(new) - tail]))
    return edits


def _depths(model: SemanticModel, unit: Unit) -> list[int]:
    """Block depth of every 0-based line."""
    count = line_count(model.document(unit))
    change = [0] * (count + 1)
    for block in model.structures[unit].blocks:
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


def _continuations(document: Document) -> set[int]:
    """The 0-based physical lines that continue a logical line (a DIM list): they keep their indentation."""
    index = document.line_index
    continued: set[int] = set()
    for line in document.placed:
        first = line.number - 1
        continued.update(range(first + 1, index.position(line.span(line.syntax.span).end).line))
    return continued


def _labelled(document: Document) -> set[int]:
    """The 0-based lines that start with a label."""
    return {line.number - 1 for line in document.placed if line.syntax.label is not None}


def _indentations(model: SemanticModel, unit: Unit, indentation: str, lines: range) -> dict[int, str]:
    """Per 0-based line with content whose indentation is the formatter's: the indentation it should have."""
    document = model.document(unit)
    depths, continued, labelled = _depths(model, unit), _continuations(document), _labelled(document)
    return {line: "" if line in labelled else indentation * depths[line] for line in lines if line not in continued}


def _keywords(document: Document, lines: range) -> dict[int, list[Span]]:
    """Per 0-based line: the spans of its keywords not written in upper case (a comment's REM included);
    none in MintMT, whose words keep their case."""
    if document.dialect is Dialect.MINTMT:
        return {}
    v3 = document.dialect is Dialect.V3
    index = document.line_index
    found: dict[int, list[Span]] = {}
    previous = None
    for token in document.tokens:
        after_jump, previous = previous in _JUMPS, previous if token.kind is TokenKind.WS else token.kind
        if token.kind in _UPPER_CASED and not after_jump and not (v3 and token.text.upper() == _V3_PROTECT):
            span = Span(token.start, token.end)
        elif token.kind is TokenKind.COMMENT:
            span = Span(token.start, token.start + _REM)
        else:
            continue
        text = document.source[span.start : span.end]
        if text != text.upper():
            line = index.position(token.start).line - 1
            if line in lines:
                found.setdefault(line, []).append(span)
    return found


def _shared(old: str, new: str) -> tuple[int, int]:
    """How many leading, then trailing, characters two texts have in common (without overlap)."""
    limit = min(len(old), len(new))
    head = 0
    while head < limit and old[head] == new[head]:
        head += 1
    tail = 0
    while tail < limit - head and old[-1 - tail] == new[-1 - tail]:
        tail += 1
    return head, tail


def _content_end(source: str, start: int) -> int:
    """Where the line starting at ``start`` ends, before its line break."""
    breaks = [found for found in (source.find("\r", start), source.find("\n", start)) if found >= 0]
    return min(breaks, default=len(source))


def _formatted(source: str, start: int, end: int, indentation: str | None, keywords: list[Span]) -> str:
    """The line ``source[start:end]`` in the house style; ``indentation`` None keeps the line's own."""
    content = start
    while content < end and source[content] in " \t":
        content += 1
    pieces = [source[start:content] if indentation is None else indentation]
    cursor = content
    for span in keywords:
        pieces += [source[cursor : span.start], source[span.start : span.end].upper()]
        cursor = span.end
    pieces.append(source[cursor:end])
    return "".join(pieces).rstrip(" \t")


def first_syntax_error(document: Document) -> Diagnostic | None:
    """The first syntax error of ``document`` in the text, if it has one: such a text is not formatted."""
    errors = (found for found in document.diagnostics if found.mint_error in SYNTAX_ERRORS)
    return min(errors, key=lambda found: found.span.start, default=None)  # the lexer's come before the parser's


class Unparsable(ValueError):
    """A text with a syntax error, left as it is; the message is ``line:column: CODE message`` of its first."""


def format_text(
    text: str, indentation: str, dialect: Dialect, *, configuration: bool = False, seen: str | None = None
) -> str:
    """``text``, a program (or with ``configuration`` a configuration file) of ``dialect``, in the house style;
    ``Unparsable`` if it has a syntax error. ``seen`` is the configuration file a program sees, whose macros
    are the program's (000:1540-1541)."""
    from mintlang.semantic.model import build_model  # noqa: PLC0415 - see the imports
    from mintlang.syntax.parser import parse  # noqa: PLC0415

    document = parse(text, dialect, macros=None if seen is None else parse(seen, dialect).macros)
    error = first_syntax_error(document)
    if error is not None:
        place = document.line_index.position(error.span.start)
        raise Unparsable(f"{place.line}:{place.column}: {error.code} {error.message}")
    model = build_model(parse("", dialect), document) if configuration else build_model(document)
    unit = Unit.CONFIGURATION if configuration else Unit.PROGRAM
    return with_edits(text, formatting_edits(model, unit, indentation))
