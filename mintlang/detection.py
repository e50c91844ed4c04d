"""Which dialect a text is written in, Mint v4 or MintMT, from the forms only MintMT has.

An editor opening a ``.mnt`` file has no header saying which Mint it holds, so
``mint.dialect = auto`` asks this module. The text is lexed as MintMT and read
for MintMT's own forms (``mintlang/MINTMT.md``):

* a ``'`` comment, at the start of a line or after code, unless it has the
  shape of v4's character constant ``'A'`` (a quote, one character, a quote);
* a two-word closer: ``End Loop``, ``End If``, ``End Event``, ``End Startup``;
* an ``Event NAME`` or ``Startup`` line (not ``event = ...``: a v4 program may
  have a variable called ``event``);
* round-bracket addressing, ``MOVER(0) = 10``: a ``(`` right after a keyword.

One of them makes the text MintMT; without any it is Mint v4, the default
dialect, so every v4 program reads as before. Mint v3 is not told apart here:
its forms are v4's as far as this reading goes (the migrator recognises it).
"""

from __future__ import annotations

import re

from mintlang.diagnostics import split_lines
from mintlang.dialect import Dialect
from mintlang.syntax.common import common_prefix, common_suffix
from mintlang.syntax.lexer import LexedLine, lex
from mintlang.syntax.tokens import TokenKind

_QUOTES = "'‘’"  # the straight quote and the typographic ones manuals print
_CHARACTER_CONSTANT = re.compile(f"[{_QUOTES}][^{_QUOTES}][{_QUOTES}]")
_NAME = re.compile(r"[A-Za-z_]\w*")
_CLOSERS = frozenset({TokenKind.ENDL, TokenKind.ENDIF, TokenKind.ENDEVENT, TokenKind.ENDSTARTUP})
# What a line must hold to show one of the forms: a quote (a ' comment), a bracket (addressing), or
# the word of a closer or an opener. The other lines, most of a v3 or v4 program, are not lexed:
# lexing every line cost most of a parse, which the migrator paid before reading anything.
_MAY_SHOW = re.compile(f"[{_QUOTES}(]|end[ \\t]|event|startup", re.IGNORECASE)


def detect_dialect(text: str) -> Dialect:
    """``Dialect.MINTMT`` when ``text`` shows a form only MintMT has, ``Dialect.V4`` otherwise."""
    return Dialect.MINTMT if _shows_any(text) else Dialect.V4


def detect_dialect_after(previous: str, found: Dialect, text: str) -> Dialect:
    """``detect_dialect(text)``, knowing that of ``previous`` was ``found``: an editor asks after
    every keystroke, and reading the whole file costs time in proportion to it. Only the lines
    that changed are read, unless they held what made ``previous`` MintMT."""
    start = common_prefix(previous, text)
    end = common_suffix(previous, text, min(len(previous), len(text)) - start)
    start = max(previous.rfind("\n", 0, start), previous.rfind("\r", 0, start)) + 1  # whole lines
    tail = previous[len(previous) - end :]
    breaks = [at for at in (tail.find("\n"), tail.find("\r")) if at >= 0]
    end = len(tail) - min(breaks) - 1 if breaks else 0
    if found is Dialect.V4:
        return Dialect.MINTMT if _shows_any(text[start : len(text) - end]) else Dialect.V4
    return Dialect.MINTMT if not _shows_any(previous[start : len(previous) - end]) else detect_dialect(text)


def _shows_any(text: str) -> bool:
    may_show = "".join(line for line in split_lines(text, keepends=True) if _MAY_SHOW.search(line))
    return any(_shows_mintmt(line) for _, line in lex(may_show, Dialect.MINTMT).lines)


def _shows_mintmt(line: LexedLine) -> bool:
    return _quote_comment(line) or _two_word_closer(line) or _block_opener(line) or TokenKind.ADDRESS in line.kinds


def _quote_comment(line: LexedLine) -> bool:
    """A ``'`` comment that is not the shape of a v4 character constant."""
    start = line.comment_start
    return start >= 0 and line.text[start] in _QUOTES and not _CHARACTER_CONSTANT.match(line.text, start)


def _two_word_closer(line: LexedLine) -> bool:
    return any(kind in _CLOSERS and len(text.split()) > 1 for kind, text in zip(line.kinds, line.texts, strict=True))


def _block_opener(line: LexedLine) -> bool:
    """``Event NAME`` or ``Startup`` alone on its line."""
    kinds, texts = line.kinds, line.texts
    if kinds == (TokenKind.STARTUP,):
        return True
    return len(kinds) == 2 and kinds[0] is TokenKind.EVENT and _NAME.fullmatch(texts[1]) is not None
