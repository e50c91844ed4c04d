"""A v4 text as the MintMT rewrites read it: its physical lines lexed as Mint v4, and what they ask for.

Every rewrite works on tokens of the project's lexer (never on raw text), so a
word inside a string or a comment is never taken for code. A rewrite asks for
``Rewrite`` (put text in place of a span) or ``Flag`` (a manual item for the line
holding a span); ``apply`` does the editing.
"""

from __future__ import annotations

from collections.abc import Iterator
from functools import cached_property

from mintlang.diagnostics import Span
from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.migrate.context import OPENING_COMMANDS
from mintlang.migrate.history import Edit
from mintlang.records import record
from mintlang.syntax.lexer import LexedLine, lex
from mintlang.syntax.tokens import Token, TokenKind

# ``text`` in place of ``span`` of the v4 text (an empty span inserts), asked for by ``rule``: the
# v3 -> v4 engine's edit, which ``History`` maps back to the original.
Rewrite = Edit


@record
class Flag:
    """A manual item from ``rule``: the line holding offset ``at`` gets a marker above it (below the
    line opening the file, ``Source.opening``)."""

    rule: str
    at: int
    reason: str


Action = Rewrite | Flag


@record(slots=False)
class Line:
    """One physical line: its number (from 1), its offset in the text, and its significant tokens."""

    number: int
    offset: int
    lexed: LexedLine

    @cached_property
    def tokens(self) -> tuple[Token, ...]:
        """The line's significant tokens (no white space, comment or line break), at file offsets."""
        lexed, offset = self.lexed, self.offset
        return tuple(
            Token(kind, text, start + offset)
            for kind, text, start in zip(lexed.kinds, lexed.texts, lexed.starts, strict=True)
        )

    @property
    def kinds(self) -> tuple[TokenKind, ...]:
        return self.lexed.kinds

    @property
    def statement_kinds(self) -> tuple[TokenKind, ...]:
        """``kinds`` without the ``:`` that end the line: before a comment (``RETURN : REM c``, as the v4
        guide advises writing a comment after code, 000:15510-15512) they separate no statement."""
        kinds = self.lexed.kinds
        end = len(kinds)
        while end and kinds[end - 1] is TokenKind.COLON:
            end -= 1
        return kinds[:end]

    @property
    def comment(self) -> Span | None:
        """Where the line's comment is, without the line break."""
        if self.lexed.comment_start < 0:
            return None
        return Span(self.offset + self.lexed.comment_start, self.offset + self.lexed.content_end)

    @property
    def blank(self) -> bool:
        """Whether the line holds no code (white space or a comment only)."""
        return not self.lexed.kinds


@record(slots=False)
class Source:
    """The v4 text of one file and its lines; ``visible`` names the macros another file defines for it
    (a configuration file's, for its program)."""

    text: str
    visible: frozenset[str] = frozenset()

    @cached_property
    def lines(self) -> tuple[Line, ...]:
        return tuple(
            Line(number, offset, lexed)
            for number, (offset, lexed) in enumerate(lex(self.text, Dialect.V4).lines, start=1)
        )

    @cached_property
    def opening(self) -> Line | None:
        """The line of the command that must stay the first of the file, REM lines included
        (``OPENING_COMMANDS``), or None: its markers go below it, as the v3 -> v4 migration's do."""
        first = next((line for line in self.lines if not line.blank), None)
        if first is None or first.kinds[0] is not TokenKind.KEYWORD:
            return None
        word = first.tokens[0].text
        return first if (database().owner(word) or word.upper()) in OPENING_COMMANDS else None

    @cached_property
    def macros(self) -> frozenset[str]:
        """The upper-case names of the macros this file can use: its own ``DEFINE`` lines' and ``visible``."""
        defined = (
            line.tokens[1].text.upper()
            for line in self.lines
            if len(line.tokens) > 1 and line.kinds[0] is TokenKind.DEFINE and line.kinds[1] is TokenKind.NAME
        )
        return self.visible | frozenset(defined)

    def tokens(self) -> Iterator[tuple[Line, int, Token]]:
        """Every significant token with its line and its index on that line."""
        for line in self.lines:
            for index, token in enumerate(line.tokens):
                yield line, index, token

    def following(self, line: Line, index: int) -> Token | None:
        """The significant token after ``line.tokens[index]`` on its line, if any."""
        return line.tokens[index + 1] if index + 1 < len(line.tokens) else None


def styled(words: str, replaced: str) -> str:
    """``words`` (written as the notes write them, ``End Loop``) in the case of the v4 word they replace:
    all capitals for ``ENDL``, all small letters for ``endl``, the notes' own case otherwise (MT-21)."""
    letters = [c for c in replaced if c.isalpha()]
    if letters and all(c.isupper() for c in letters):
        return words.upper()
    if letters and all(c.islower() for c in letters):
        return words.lower()
    return words


def touches(token: Token, other: Token) -> bool:
    """Whether ``other`` follows ``token`` with nothing between them."""
    return token.end == other.start


def span(token: Token) -> Span:
    return Span(token.start, token.end)
