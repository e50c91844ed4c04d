"""Every character of a source belongs to exactly one token: the tokens join back to it.

Checked on every corpus file, on generated text, and through the byte-level
reading of files in the encodings old Windows tools wrote.
"""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

import mintlang
from mintlang.source import decode
from mintlang.syntax.tokens import TokenKind
from tests.corpus_files import CORPUS

CORPUS_FILES = sorted(p for p in CORPUS.rglob("*") if p.suffix in (".mnt", ".cfg"))

MINT_FRAGMENTS = st.sampled_from(
    [
        "SPEED", "sp", "MOVEA", "POS", ".1", "[0,1]", " = ", "10", ",", ";", ":", "REM note", "\n", "\r\n",
        "\r", "\t", "  ", "#label", "#", "GOSUB ", "IF ", " THEN ", " DO", "ELSE", "ENDIF", "FOR i = 1 TO 5",
        "NEXT", "'A'", "‘b’", '"text"', "“quoted”", '"open', "011011", "05", "0xFF_00", ".5", "(", ")",
        "DEFINE m = 1 : GO", "m", "DIM a(3) = 1,", "PRINT #1 ", "?", "&", "|", "!", "~", "^", "..", "é",
        "\u00a0", "\ufeff", "€", "\x00", "\x7f", "\x1a",
    ]
)  # fmt: skip


def _joined(source: str, dialect: str = "v4") -> str:
    return "".join(token.text for token in mintlang.parse(source, dialect).tokens)


@pytest.mark.parametrize("path", CORPUS_FILES, ids=lambda path: str(path.relative_to(CORPUS)))
@pytest.mark.parametrize("dialect", ["v4", "v3"])
def test_corpus_file_round_trips(path, dialect: str) -> None:
    source = path.read_text("utf-8")
    assert _joined(source, dialect) == source


@given(st.text())
def test_any_text_round_trips(source: str) -> None:
    assert _joined(source) == source


@given(st.lists(MINT_FRAGMENTS, max_size=40).map("".join))
def test_mint_like_text_round_trips(source: str) -> None:
    assert _joined(source) == source
    assert _joined(source, "v3") == source


def test_line_endings_tabs_and_trailing_spaces_survive() -> None:
    source = "SPEED = 10   \r\n\tGO\rPAUSE IDLE\t\n\nREM ünïcödé “quotes”  \r\n"
    assert _joined(source) == source


@pytest.mark.parametrize(
    ("data", "encoding"),
    [
        ("REM café\r\nSPEED = 10\r\n".encode(), "utf-8"),
        ("REM café — “quotes”\r\n".encode("cp1252"), "cp1252"),
        (b"REM \x81\x8d\x90 bytes cp1252 leaves undefined\n", "latin-1"),
    ],
)
def test_files_in_old_encodings_decode_to_the_same_bytes(data: bytes, encoding: str) -> None:
    text, found = decode(data)
    assert found == encoding
    assert _joined(text).encode(found) == data


@given(st.binary(max_size=400))
def test_any_bytes_decode_and_round_trip(data: bytes) -> None:
    text, encoding = decode(data)
    assert _joined(text).encode(encoding) == data


@given(st.lists(MINT_FRAGMENTS, max_size=40).map("".join), st.integers(0, 400), st.integers(0, 400))
def test_the_tokens_of_a_range_are_its_whole_lines_of_the_stream(source: str, start: int, length: int) -> None:
    document = mintlang.parse(source)
    start = min(start, len(source))
    end = min(start + length, len(source))
    found = document.tokens_in(start, end)
    # every token that holds one of the offsets, or ends at the first (a word before the cursor); a line
    # break that ends there belongs to the line before, which holds none of them
    touching = [
        token
        for token in document.tokens
        if token.start <= end and (start < token.end or (start == token.end and token.kind is not TokenKind.NEWLINE))
    ]
    assert all(token in found for token in touching)
    if found:
        first, joined = found[0].start, "".join(token.text for token in found)
        assert source[first : first + len(joined)] == joined  # whole lines, in order, nothing left out
        assert first == 0 or source[first - 1] in "\r\n"
