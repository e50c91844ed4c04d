"""Which dialect a text is written in, Mint v4 or MintMT, from the forms only MintMT has.

An editor opening a ``.mnt`` file has no header saying which Mint it holds, so
``mint.dialect = auto`` asks this module. The text is lexed as MintMT and read
for MintMT's own forms (``mintlang/MINTMT.md``):

* a ``'`` comment, at the start of a line or after code, unless it has the
  shape of v4's character constant ``'A'`` (a quote, one character, a quote);
* a two-word closer: ``End Loop``, ``End If``, ``End Event``, ``End Startup``;
* an ``Event NAME`` or ``Startup`` line (not ``event = ...``: a v4 program may
  have a variable called ``event``);
* round-bracket addressing, ``MOVER(0) = 10``: a ``(`` right after a keyword that takes
  axes or channels. After one that takes neither, such as ``LOCATE (col + 1), 2`` in a
  v3 or v4 program, the bracket only groups the first operand; after a name the text
  declares as an array (``DIM adc(4)``, legal in v3, where ``adc`` is no keyword), it
  holds the element's index.

One of them makes the text MintMT; without any it is Mint v4, the default
dialect, so every v4 program reads as before. Mint v3 is not told apart here:
its forms are v4's as far as this reading goes (the migrator recognises it).

The command-line tools read a file as v4 unless told otherwise; ``dialect_hint``
is the line they print when such a file shows MintMT's forms.
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Addressing
from mintlang.records import record
from mintlang.syntax.common import shared_ends
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
# what a line declaring an array holds, DIM OFFLINE adc(4) too: a match only makes the editor read
# the whole text again, so it may match more; no word boundary, as the lexer reads ``MOVER.0DIM a(2)``
# as a number before the DIM
_DIM = re.compile(r"dim.*\(", re.IGNORECASE)
_LINE_END = re.compile(r"\r\n|\r|\n")  # as ``split_lines`` ends a line


@record
class MintMTForm:
    """The first form of a text that only MintMT has: its line (from 1) and what it is, as a reader would name it."""

    line: int
    what: str


def detect_dialect(text: str) -> Dialect:
    """``Dialect.MINTMT`` when ``text`` shows a form only MintMT has, ``Dialect.V4`` otherwise."""
    return Dialect.MINTMT if _shows_any(text) else Dialect.V4


def first_mintmt_form(text: str) -> MintMTForm | None:
    """The first form of ``text`` that only MintMT has; None for a text ``detect_dialect`` finds v4."""
    numbered = _candidates(text)
    if not numbered:  # nothing to lex: the MintMT vocabulary would be built for nothing
        return None
    lexed = [line for _, line in lex("".join(line for _, line in numbered), Dialect.MINTMT).lines]
    arrays = _arrays(lexed)
    for (number, _), line in zip(numbered, lexed, strict=False):  # the lexer may add an empty last line
        if (what := _form(line, arrays)) is not None:
            return MintMTForm(number, what)
    return None


def dialect_hint(name: str, text: str, dialect: Dialect) -> str | None:
    """The line a tool prints when it reads the file ``name`` as Mint v4, as no one chose its dialect, though
    the text shows a form only MintMT has: the v4 errors such a file gets never say which option is missing."""
    if dialect is not Dialect.V4 or (form := first_mintmt_form(text)) is None:
        return None
    seen = f"{form.what} on line {form.line}"
    return f"hint: {name} looks like MintMT ({seen}) but was read as Mint v4: run with --dialect mintmt"


def detect_dialect_after(previous: str, found: Dialect, text: str) -> Dialect:
    """``detect_dialect(text)``, knowing that of ``previous`` was ``found``: an editor asks after
    every keystroke, and reading the whole file costs time in proportion to it. Only the lines
    that changed are read, unless they held what made ``previous`` MintMT."""
    start, end = shared_ends(previous, text)
    start = max(previous.rfind("\n", 0, start), previous.rfind("\r", 0, start)) + 1  # whole lines
    tail = previous[len(previous) - end :]
    breaks = [at for at in (tail.find("\n"), tail.find("\r")) if at >= 0]
    end = len(tail) - min(breaks) - 1 if breaks else 0
    typed, removed = text[start : len(text) - end], previous[start : len(previous) - end]
    # a form typed may be an array's element declared elsewhere, and a DIM typed or removed makes or unmakes one
    if found is Dialect.V4:
        return detect_dialect(text) if _shows_any(typed) or _DIM.search(removed) else Dialect.V4
    return detect_dialect(text) if _shows_any(removed) or _DIM.search(typed) else Dialect.MINTMT


def _candidates(text: str) -> list[tuple[int, str]]:
    """The lines of ``text`` that ``_MAY_SHOW`` finds something in, with their line ends (as
    ``split_lines(text, keepends=True)`` has them) and their numbers from 1. The text is searched
    at once and the lines between never made: splitting a 10,000-line program into lines to search
    each cost a third of what lexing the few found costs."""
    found: list[tuple[int, str]] = []
    number, counted = 1, 0  # the number of the line starting at ``counted``
    taken = 0  # where the line last taken ends
    for match in _MAY_SHOW.finditer(text):
        at = match.start()
        if at < taken:
            continue  # on that line too
        start = max(text.rfind("\n", 0, at), text.rfind("\r", 0, at)) + 1
        number += len(_LINE_END.findall(text, counted, start))
        counted = start
        end = _LINE_END.search(text, at)
        taken = end.end() if end is not None else len(text)
        found.append((number, text[start:taken]))
    return found


def _shows_any(text: str) -> bool:
    return first_mintmt_form(text) is not None


def _arrays(lines: list[LexedLine]) -> frozenset[str]:
    """The upper-case names ``lines`` declare as arrays: ``DIM name(``, or v3's ``DIM OFFLINE name(``
    (an array kept on the memory card, 001:1588-1589)."""
    return frozenset(name for line in lines for name in _declared(line))


def _declared(line: LexedLine) -> Iterator[str]:
    """The array names ``line``'s DIM statements declare with a ``(`` the lexer reads as an address."""
    kinds = line.kinds
    if TokenKind.DIM not in kinds:
        return  # most lines: their token texts are not made (``texts`` makes them at every call)
    texts = line.texts
    for index, kind in enumerate(kinds):
        if kind is TokenKind.DIM:
            name = index + 1
            if name < len(texts) and texts[name].upper() == "OFFLINE":
                name += 1
            if name + 1 < len(kinds) and kinds[name + 1] is TokenKind.ADDRESS:
                yield texts[name].upper()


def _form(line: LexedLine, arrays: frozenset[str]) -> str | None:
    """The MintMT form ``line`` shows, named as written (``End If``, ``MOVER(…)``), the ``(`` after a
    name in ``arrays`` aside; None for none."""
    kinds = line.kinds
    if _quote_comment(line):
        return "a ' comment"
    if any(closer in kinds for closer in _CLOSERS):  # the token texts are made for the few lines that need them
        closers = (text.split() for kind, text in zip(kinds, line.texts, strict=True) if kind in _CLOSERS)
        if (two_words := next((words for words in closers if len(words) > 1), None)) is not None:
            return " ".join(two_words)
    if _block_opener(line):
        return " ".join(line.texts)
    if (addressed := _addressed(line, arrays)) is not None:
        return f"{addressed}(…)"
    return None


def _addressed(line: LexedLine, arrays: frozenset[str]) -> str | None:
    """The first keyword of ``line`` written with its axes or channels in round brackets; a keyword no
    axis or channel addresses (LOCATE, LINE, WAIT) takes none, so its ``(`` opens an expression, and
    a word the text declares as an array is the array's name."""
    kinds = line.kinds
    if TokenKind.ADDRESS not in kinds:
        return None
    texts = line.texts
    keywords = database().keywords_of(Dialect.MINTMT)
    for index, kind in enumerate(kinds):
        if kind is TokenKind.ADDRESS and index > 0 and texts[index - 1].upper() not in arrays:
            word = texts[index - 1]
            keyword = keywords.get(database().owner(word) or word.upper())
            if keyword is None or keyword.addressing is not Addressing.NONE:
                return word
    return None


def _quote_comment(line: LexedLine) -> bool:
    """A ``'`` comment that is not the shape of a v4 character constant."""
    start = line.comment_start
    return start >= 0 and line.text[start] in _QUOTES and not _CHARACTER_CONSTANT.match(line.text, start)


def _block_opener(line: LexedLine) -> bool:
    """``Event NAME`` or ``Startup`` alone on its line."""
    kinds = line.kinds
    if kinds == (TokenKind.STARTUP,):
        return True
    return len(kinds) == 2 and kinds[0] is TokenKind.EVENT and _NAME.fullmatch(line.texts[1]) is not None
