"""A Mint v3 reading carried over to Mint v4: the lines both dialects read alike are not read again.

Line by line, the dialects differ in what a word is (keywords, constants, abbreviations: ``DE``
is DECEL in v3 and DRIVEENABLE in v4), in how AND binds beside OR and XOR (v3 binds AND
tighter: the two grammars swap those levels and nothing else), in the numbers only v4 writes
(``0x1F``, ``1_000``) or finds too large (a literal of 34 characters or more may be), and in v3's
spaced relations (``< =``). A line whose words are each the
same kind of token naming the same keyword in both, that does not mix AND with OR or XOR, and
whose v3 reading found nothing (no diagnostic, no macro defined or expanded) lexes and parses
as Mint v4 into what v3 made of it. Its lexed lines and syntax go into v4's per-line caches, so
a v4 parse of the same text finds them there: a migration reads its result as v4 right after
reading it as v3. ``tests/core/test_v4_reads_v3_lines_alike.py`` holds every line carried over
to a fresh v4 reading.
"""

from __future__ import annotations

import re
from operator import sub

from mintlang.dialect import Dialect
from mintlang.keyworddb.model import Controller
from mintlang.syntax import lexer, parser
from mintlang.syntax.grammar import ParseFailure, parse_kinds
from mintlang.syntax.lexer import SHORTEST_TOO_LARGE, LexedLine
from mintlang.syntax.parser import Document
from mintlang.syntax.tokens import TokenKind
from mintlang.syntax.vocabulary import Vocabulary, vocabulary

_NOTEQUAL, _LESSEQUAL, _MOREEQUAL = TokenKind.NOTEQUAL, TokenKind.LESSEQUAL, TokenKind.MOREEQUAL  # v3 reads ``< =``
_SPACEABLE = frozenset({_NOTEQUAL, _LESSEQUAL, _MOREEQUAL})
_STRING, _CHAR, _NUMBER = TokenKind.STRING, TokenKind.CHAR, TokenKind.NUMBER
_OR = frozenset({TokenKind.OR, TokenKind.XOR})
# Every word of a line's code, upper-cased, and some pieces of its numbers and labels besides: a
# line is carried when all of them are alike, so the extra pieces can only keep one from it.
_WORD = re.compile("[A-Z_][A-Z0-9_]*")


def carry_to_v4(document: Document, controller: Controller | None) -> None:
    """Put the lines of ``document``, a Mint v3 reading, that Mint v4 on ``controller`` reads alike
    into v4's per-line caches."""
    if document.dialect is not Dialect.V3:
        raise ValueError(f"a Mint v3 reading is carried over, not a {document.dialect} one")
    words = _Words(document.context.controller, controller)
    lines = [line for _, line in document.physical]
    placed = document.placed
    # A logical line's physical lines run to the next one's first: those between hold no tokens.
    bounds = [line.number - 1 for line in placed]
    bounds.append(len(lines))
    _carry_lexed(words, lines[: bounds[0]])
    for index, line in enumerate(placed):
        if parser.knows(line.syntax.text, Dialect.V4, controller):
            continue  # parsed as v4 already (a line above, an earlier reading of the run), lexed with it
        physical = lines[bounds[index] : bounds[index + 1]]
        if _carry_lexed(words, physical) and _parses_alike([each.kinds for each in physical]):
            parser.remember(line, Dialect.V4, controller)


def _carry_lexed(words: _Words, lines: list[LexedLine]) -> bool:
    """Put those of ``lines`` that Mint v4 lexes alike into its lexer's cache: whether all of them are."""
    alike = [words.lexes_alike(line) for line in lines]
    for line, same in zip(lines, alike, strict=True):
        if same:
            lexer.remember(Dialect.V4, line)
    return all(alike)


def _parses_alike(lines: list[tuple[TokenKind, ...]]) -> bool:
    """Whether the tokens of a logical line's physical lines parse as v3, and into the same tree
    with either grammar."""
    kinds = lines[0] if len(lines) == 1 else tuple(kind for line in lines for kind in line)
    if TokenKind.AND in kinds and not _OR.isdisjoint(kinds):
        return False
    return not isinstance(parse_kinds(kinds, Dialect.V3), ParseFailure)


class _Words:
    """Which words are the same token, naming the same keyword, in both dialects (worked out once a word)."""

    def __init__(self, v3_controller: Controller | None, v4_controller: Controller | None) -> None:
        self._lexed = (vocabulary(Dialect.V3), vocabulary(Dialect.V4))  # the lexer's: no controller
        self._built = (vocabulary(Dialect.V3, v3_controller), vocabulary(Dialect.V4, v4_controller))
        self._same: set[str] = set()
        self._differ: set[str] = set()

    def lexes_alike(self, line: LexedLine) -> bool:
        if line.issues:
            return False
        kinds = line.kinds  # searched by identity: hashing a kind costs a Python call
        if (_NOTEQUAL in kinds or _LESSEQUAL in kinds or _MOREEQUAL in kinds) and _spaced(line):
            return False
        if len(line.text) >= SHORTEST_TOO_LARGE and _long_number(line):  # no token is longer than its line
            return False
        if line.text.startswith("PROTECT") and not _one_word_password(line):
            return False
        words = set(_WORD.findall(_code(line).upper()))
        if words <= self._same:
            return True
        if not words.isdisjoint(self._differ):
            return False
        for word in words - self._same:
            (self._same if self._alike(word) else self._differ).add(word)
        return words <= self._same

    def _alike(self, upper: str) -> bool:
        (v3, v4), (built_v3, built_v4) = self._lexed, self._built
        if _kind(v3, upper) is not _kind(v4, upper):
            return False
        if built_v3.canonical.get(upper) != built_v4.canonical.get(upper):
            return False
        return not upper[-1].isdigit() or built_v3.split_channel(upper) == built_v4.split_channel(upper)


def _code(line: LexedLine) -> str:
    """The text of ``line`` without its comment, strings and characters (a space in place of each):
    the words a v3 program prints, "at" or "DE", are no tokens."""
    text = line.text if line.comment_start < 0 else line.text[: line.comment_start]
    kinds = line.kinds
    if _STRING not in kinds and _CHAR not in kinds:
        return text
    pieces, last = [], 0
    for kind, start, end in zip(kinds, line.starts, line.ends, strict=True):
        if kind is _STRING or kind is _CHAR:
            pieces.append(text[last:start])
            last = end
    pieces.append(text[last:])
    return " ".join(pieces)


def _one_word_password(line: LexedLine) -> bool:
    """Whether the password a v3 ``PROTECT`` line gives, the rest of its line (001:11089-11092), is one word,
    as v4 reads it too: ``PROTECT my pass`` or ``PROTECT abc : REM x`` are other statements in v4."""
    if len(line.kinds) != 2 or line.kinds[1] is not TokenKind.NAME:
        return True  # no password read: the line was lexed as any other
    return _WORD.fullmatch(line.text[line.starts[1] : line.ends[1]].upper()) is not None


def _spaced(line: LexedLine) -> bool:
    """Whether v3 read a relation written with a space inside (``< =``) on ``line``."""
    spaceable = zip(line.kinds, line.starts, line.ends, strict=True)
    return any(kind in _SPACEABLE and end - start != 2 for kind, start, end in spaceable)


def _long_number(line: LexedLine) -> bool:
    """Whether a number on ``line`` is long enough for a v4 reading to check its size, which v3's does not.

    Most lines have no token that long at all: the lengths are worked out in C first, and the tokens
    looked at one by one only beside a long one (a string, most often)."""
    if max(map(sub, line.ends, line.starts), default=0) < SHORTEST_TOO_LARGE:
        return False
    tokens = zip(line.kinds, line.starts, line.ends, strict=True)
    return any(kind is _NUMBER and end - start >= SHORTEST_TOO_LARGE for kind, start, end in tokens)


def _kind(words: Vocabulary, upper: str) -> TokenKind:
    """The token a word is to the lexer (as ``lexer._lex_line`` classifies it)."""
    return words.words.get(upper) or words.classify_unlisted(upper)
