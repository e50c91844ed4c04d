"""A Mint v3 reading carried over to Mint v4 (``mintlang.syntax.alike``) changes no v4 reading:
parsing a text as v4 after its v3 reading was carried over gives what parsing it cold gives,
line for line, on every program of the corpora for two controllers, and on lines written where
the dialects part (a word that is another keyword, AND beside OR, v4's numbers, v3's spaced
relations, macros). The lines both read alike share the v3 syntax; the others are read as v4."""

from __future__ import annotations

from pathlib import Path

import pytest

from mintlang.caching import apart
from mintlang.dialect import Dialect
from mintlang.syntax.alike import carry_to_v4
from mintlang.syntax.parser import Document, parse

TESTS = Path(__file__).parents[1]
PROGRAMS = sorted((*(TESTS / "corpus").rglob("*.mnt"), *(TESTS / "conformance").rglob("*.mnt")))
CONTROLLERS = ("nextmove-pci", "mintdrive")

# Each line differs between the dialects in one way the carrying must see.
PARTING = [
    "DE = 1",  # DECEL in v3, DRIVEENABLE in v4
    "MA.1 = 10 : GR = 2",  # MOVEA / GEARN abbreviations
    "a = b AND c OR d",  # AND binds tighter in v3
    "a = b XOR c",  # no v3 word
    "OUT1 = 1 : FOR i = 1 TO 2 : NEXT i",  # v3 spellings of their own (OUT1, I)
    "IF a & b | c THEN PRINT a",
    "a = b XOR c AND d",
    "IF a < = b THEN PRINT a",  # v3 reads a spaced relation as one
    "IF a > = b OR a < > c THEN GO",
    "a = 0x1F : b = 1_000",  # numbers v4 alone writes
    "a = 123456789012345678901234567890123456789012345",  # too large for v4's numbers (000:714-716)
    "a = _FORWARD : b = _SERVO",  # constants of one dialect
    "HMSPEED.0 = 10 : HOMESPEED.0 = 10",  # a v3 keyword, a v4 keyword
    "a = IN3 + ANALOG1",  # channels glued to the keyword
    "DIM t(3) = 1,2,",  # a DIM list continued
    "  3",
    "DEFINE twice = 2 * a",  # a macro defined, then used
    "b = twice",
    "PRINT SQRT(4.4)",  # an array in v3, a function in v4
    "DRIVEENABLE = 1",  # a variable in v3
    "GOSUB sub1 : #sub1",  # a label after a statement: an error
]
# Lines with the same words and, without AND beside OR, the same grammar: read alike.
ALIKE = [
    "x = y",
    "PRINT a, b;",
    "a = b AND c",
    "b = c OR d OR e",
    "IF a <= b THEN GO.0",
    "MOVEA.0 = 100 : GO.0",
    "PAUSE IDLE[0,1] : OUT.1 = 1",
    "FOR n = 1 TO 10 : NEXT",
    "PRINT \"at the DE end: \", a, 'A' : REM HMSPEED",  # words of strings and comments are no tokens
]


def _view(document: Document) -> tuple[object, ...]:
    placed = tuple((line.origin, line.number, line.syntax) for line in document.placed)
    return placed, tuple(document.physical), document.diagnostics, document.definitions, document.expansions


def _carried(text: str, controller: str) -> tuple[Document, Document]:
    """The v3 reading of ``text``, and its v4 reading after the v3 one was carried over."""
    with apart():
        v3 = parse(text, Dialect.V3)
        carry_to_v4(v3, controller)  # type: ignore[arg-type]
        return v3, parse(text, Dialect.V4, controller=controller)


def _cold(text: str, controller: str) -> Document:
    with apart():
        return parse(text, Dialect.V4, controller=controller)


@pytest.mark.parametrize("controller", CONTROLLERS)
@pytest.mark.parametrize("path", PROGRAMS, ids=lambda path: str(path.relative_to(TESTS)))
def test_a_carried_reading_is_the_cold_one(path: Path, controller: str) -> None:
    text = path.read_text(encoding="utf-8")
    assert _view(_carried(text, controller)[1]) == _view(_cold(text, controller))


@pytest.mark.parametrize("controller", CONTROLLERS)
def test_lines_where_the_dialects_part_are_read_as_v4(controller: str) -> None:
    text = "\n".join(PARTING + ALIKE) + "\n"
    v3, v4 = _carried(text, controller)
    assert _view(v4) == _view(_cold(text, controller))
    pairs = zip(v3.placed, v4.placed, strict=True)
    shared = [new.syntax.text.strip() for old, new in pairs if old.syntax is new.syntax]
    assert shared == ["DIM t(3) = 1,2,\n  3", *ALIKE]


def test_only_a_v3_reading_is_carried_over() -> None:
    with pytest.raises(ValueError, match="a Mint v3 reading"):
        carry_to_v4(parse("PRINT 1\n", Dialect.V4), None)
