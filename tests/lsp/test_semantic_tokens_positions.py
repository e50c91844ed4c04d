"""Semantic tokens are placed by a forward pass over each line: the columns must be those that
converting each token's line up to it gives, in every position encoding.

The reference below encodes, for each token, its line up to it with Python's
codecs: simple, and quadratic on a long line, which is why the server no
longer places tokens one at a time.
"""

from __future__ import annotations

import re
from bisect import bisect_right

import pytest
from hypothesis import given
from hypothesis import strategies as st
from lsprotocol import types

from mintlang.diagnostics import Span
from mintlang.keyworddb import database
from mintlang.lsp.features.semantic_tokens import TOKEN_TYPES, encode
from mintlang.lsp.positions import Positions, columns
from mintlang.lsp.workspace import Analyses, Snapshot
from mintlang.syntax.nodes import identity
from mintlang.syntax.tokens import TRIVIA, TokenKind
from tests.lsp.conftest import units

ENCODINGS = [types.PositionEncodingKind.Utf16, types.PositionEncodingKind.Utf8, types.PositionEncodingKind.Utf32]
CAM = "DIM cam(2000) = " + ", ".join(str(i % 97) for i in range(2000)) + " : REM cam profile in µm\nPRINT cam(1)\n"
MIXED = 'DIM a\r\n\tREM 😀 é\r\nPRINT "😀µ" ; a : a = 2 : REM 𝄞 ° \rlast😀 a\n' + CAM


def snapshot_of(text: str, encoding: str) -> Snapshot:
    return Analyses(read=lambda uri: None, encoding=encoding).snapshot("file:///colours.mnt", text, 1)


def reference(snapshot: Snapshot, within: Span | None = None) -> list[tuple[int, int, int, str]]:
    """(line, column, length, type) of each coloured token, each placed on its own."""
    symbols, text, encoding = snapshot.model.symbols, snapshot.document.source, snapshot.positions.encoding
    starts = [0, *(match.end() for match in re.finditer(r"\r\n|\r|\n", text))]
    found = []
    for token in snapshot.document.tokens:
        if token.kind in TRIVIA - {TokenKind.COMMENT} or (within and not within.start <= token.start < within.end):
            continue
        if token.kind is TokenKind.NAME:
            name = identity(token.text)
            labelled = name in symbols.labels[snapshot.unit] and name not in symbols.variables
            kind = "macro" if name in symbols.macros else "function" if labelled else "variable"
            declared = name in symbols.variables and symbols.variables[name].definitions
            if kind == "variable" and not declared and database().lookup_v3(token.text) is not None:
                kind = "keyword"  # a Mint v3 word left in v4 code
        else:
            kind = {
                TokenKind.NUMBER: "number",
                TokenKind.COMMENT: "comment",
                TokenKind.STRING: "string",
                TokenKind.DIM: "keyword",
                TokenKind.PRINT: "keyword",
                TokenKind.KEYWORD: "keyword",  # CAM
            }.get(token.kind)  # the kinds of the texts below; their punctuation gets no colour
        if kind is not None:
            line = bisect_right(starts, token.start) - 1
            column = units(text[starts[line] : token.start], encoding)
            found.append((line, column, units(token.text, encoding), kind))
    return found


def decoded(data: list[int]) -> list[tuple[int, int, int, str]]:
    """The absolute tokens of a relative encoding."""
    found, line, column = [], 0, 0
    for index in range(0, len(data), 5):
        delta_line, delta_start, length, kind, _ = data[index : index + 5]
        line += delta_line
        column = column + delta_start if delta_line == 0 else delta_start
        found.append((line, column, length, TOKEN_TYPES[kind]))
    return found


@pytest.mark.parametrize("encoding", ENCODINGS)
@pytest.mark.parametrize("text", [CAM, MIXED], ids=["cam-table-in-µm", "tabs-crlf-astral"])
def test_a_long_line_gets_the_columns_a_position_per_token_gives(text, encoding):
    snapshot = snapshot_of(text, encoding)
    expected = reference(snapshot)
    assert len(expected) > 2000
    assert decoded(encode(snapshot)) == expected


@pytest.mark.parametrize("encoding", ENCODINGS)
def test_a_range_gets_the_tokens_starting_in_it(encoding):
    snapshot = snapshot_of(MIXED, encoding)
    for start, end in [(0, 9), (9, 40), (MIXED.index("last"), MIXED.index("cam(2000)") + 500), (3, 3)]:
        within = Span(start, end)
        in_range = decoded(encode(snapshot, within))
        assert in_range == reference(snapshot, within)


LINE_BREAKS = st.sampled_from(["\n", "\r\n", "\r"])
CHARACTERS = st.one_of(st.sampled_from('aZ09 \t:"µé°€😀𝄞'), st.characters(exclude_categories=["Cs"]))


@given(st.lists(st.tuples(st.text(CHARACTERS, max_size=30), LINE_BREAKS), max_size=6), st.data())
def test_columns_in_one_pass_are_those_of_positions(lines, data):
    text = "".join(content + brk for content, brk in lines)
    for encoding in ENCODINGS:
        positions = Positions(text, encoding)
        for number in range(positions.line_count):
            start = positions.line_start(number)
            line = text[start : positions.line_start(number + 1)] if number + 1 < positions.line_count else text[start:]
            content = len(line.rstrip("\r\n"))
            offsets = sorted(data.draw(st.lists(st.integers(0, content), max_size=8)))
            expected = [positions.position(start + offset).character for offset in offsets]
            assert columns(line, offsets, encoding) == expected


BASE = 'DEFINE speed = 10\nDIM a\n#lbl\na = speed\nGOSUB lbl\nPRINT a ; "é"\nRETURN\n'
TYPED = [
    "speed",
    "lbl",
    "a",
    "\n",
    "DEFINE lbl = 2\n",
    "DIM lbl\n",
    "DIM speed\n",
    " ",
    "é😀",
    ":",
    "GAIN",
    "DIM gain\n",
]


@given(st.integers(0, len(BASE)), st.integers(0, 4), st.sampled_from(["", *TYPED]), st.sampled_from(ENCODINGS))
def test_after_an_edit_each_line_gets_the_colours_of_its_names_now(where, removed, typed, encoding):
    # a line's encoding is kept while its text and the colours of names stay the same: a DEFINE or
    # a DIM added elsewhere recolours the lines that use the name
    encode(snapshot_of(BASE, encoding))
    text = BASE[:where] + typed + BASE[where + removed :]
    edited = snapshot_of(text, encoding)
    assert encode(edited) == encode(edited, Span(0, len(text)))  # a range is coloured afresh, token by token
