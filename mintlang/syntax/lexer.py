"""The lossless, line-oriented Mint lexer.

One compiled regular expression finds the next lexeme; a little state decides
what it means where Mint's grammar depends on position:

* ``#name`` is a label only as the first non-blank of a line (else ``#`` selects a terminal);
* ``.`` right after a keyword is the dot parameter (``SPEED.1``), elsewhere it starts a number (``.5``);
* ``REM`` comments the rest of the line; ``IN3`` is keyword IN with channel 3;
* a number with a leading zero is binary (``011011``), so ``05`` is invalid;
* in v3, ``> =``, ``< =`` and ``< >`` are the relations ``>=``, ``<=`` and ``<>``;
* in MintMT, ``'`` comments the rest of the line, ``End Loop`` (``If``, ``Event``,
  ``Startup``) is one closing token, a ``Then`` that ends its line opens a block
  (it lexes as ``DO``), and ``(`` right after a keyword opens its axes
  (``ADDRESS``: ``MOVER(0) = 10``).

Lexing a line depends only on the line's text, so results are cached per line:
programs repeat lines (``GO``, ``PAUSE IDLE``, ``RETURN``) and the language
server re-lexes on every keystroke.
"""

from __future__ import annotations

import re
from array import array
from collections.abc import Iterator, Sequence
from sys import intern
from typing import TypeVar, overload

from mintlang import binary32
from mintlang.caching import LINES_KEPT, RecentCache
from mintlang.codes import mint_error, own
from mintlang.diagnostics import Diagnostic, Edit, Fix, Span, quoted
from mintlang.dialect import Dialect
from mintlang.records import record
from mintlang.syntax.moved import MovedOffsets, Spliced
from mintlang.syntax.nodes import number_value
from mintlang.syntax.tokens import BYTE_ORDER_MARK, Token, TokenKind, end_of_file_mark
from mintlang.syntax.vocabulary import Vocabulary, vocabulary

_K = TokenKind
T = TypeVar("T")

_SPACE = " \t\f\v\u00a0" + BYTE_ORDER_MARK
_TYPOGRAPHIC_QUOTES = "\u201c\u201d\u201e\u201f\u2033"
_TYPOGRAPHIC_APOSTROPHES = "\u2018\u2019"
_DOUBLE = '"' + _TYPOGRAPHIC_QUOTES
_SINGLE = "'" + _TYPOGRAPHIC_APOSTROPHES
# A lexeme with the blanks before it: a separate match for the blanks was a third of the matches.
# Blanks at the end of the line match alone, with no group.
_LEXEME = re.compile(
    f"[{_SPACE}]*+(?:"
    + "|".join(
        (
            r"(?P<word>[A-Za-z_][A-Za-z0-9_]*)",
            r"(?P<number>0[xX][0-9A-Za-z_]*|[0-9][0-9A-Za-z_]*(?:\.[0-9]*)?|\.[0-9]+)",
            f"(?P<string>[{_DOUBLE}][^{_DOUBLE}\r\n]*[{_DOUBLE}]?)",
            # up to the closing quote, so that 'ab' is one bad constant, not two
            f"(?P<char>[{_SINGLE}](?:[^{_SINGLE}\r\n]*[{_SINGLE}]|[^{_SINGLE}\r\n]?))",
            r"(?P<hash>\#[A-Za-z0-9_]*)",
            r"(?P<punct><>|<=|>=|[-<>=+*/%&|!~^()\[\],;:?.])",
            f"(?P<invalid>[^{_SPACE}\r\nA-Za-z0-9_{_DOUBLE}{_SINGLE}#<>=+*/%&|!~^()\\[\\],;:?.\\-]+)",
        )
    )
    + ")?"
)
_LINE = re.compile(r"[^\r\n]*(?:\r\n|\r|\n)?")
# v3 reads a two-character relation with blanks inside: PAUSE DEMAND > = 50 (v3 guide 3096)
_SPACED_RELATION = re.compile(f"<[{_SPACE}]+[=>]|>[{_SPACE}]+=")
_DIGITS_AFTER_DOT = re.compile(r"[0-9]+")
# A v3 password is the rest of the line after an upper-case PROTECT opening it: letters, numbers, spaces and
# punctuation, a REM included (001:11089-11092); the lines after it are read as any others.
_V3_PASSWORD = re.compile(f"[{_SPACE}]+([^{_SPACE}](?:.*[^{_SPACE}])?)")

_PUNCTUATION: dict[str, TokenKind] = {
    "<>": _K.NOTEQUAL,
    "<=": _K.LESSEQUAL,
    ">=": _K.MOREEQUAL,
    "<": _K.LESSTHAN,
    ">": _K.MORETHAN,
    "=": _K.EQUAL,
    "+": _K.PLUS,
    "-": _K.MINUS,
    "*": _K.STAR,
    "/": _K.SLASH,
    "%": _K.MOD,
    "&": _K.AND,
    "|": _K.OR,
    "!": _K.NOT,
    "~": _K.TILDE,
    "^": _K.CIRCUMFLEX,
    "(": _K.LPAR,
    ")": _K.RPAR,
    "[": _K.LSQB,
    "]": _K.RSQB,
    ",": _K.COMMA,
    ";": _K.SEMICOLON,
    ":": _K.COLON,
    "?": _K.PRINT,
    ".": _K.DOT,
}
# After these (with no space between), "." is the dot parameter, not a number. A user
# name counts too: "DRIVENABLE.0" is a misspelt keyword (3007), never a name and ".0".
_DOT_OWNERS = frozenset({_K.KEYWORD, _K.FUNCTION, _K.DOT, _K.AXES, _K.NAME})


@record
class LexedLine:
    """One physical line, lexed: offsets are relative to the line's start.

    Only the significant tokens are kept, as the parallel arrays the parser
    reads. Trivia need not be stored: between significant tokens there is only
    white space, and after them white space, a REM comment and the line break,
    so ``tokens()`` rebuilds the lossless list when a tool asks for it. Nor are
    the tokens' texts: each is the line's text from its start to its end, cut
    when asked for (``texts``). Lines with the same token kinds share one
    ``kinds`` tuple.
    """

    text: str
    issues: tuple[Diagnostic, ...]
    kinds: tuple[TokenKind, ...]
    starts: tuple[int, ...]
    ends: tuple[int, ...]
    comment_start: int  # where a REM comment starts, or -1

    @property
    def length(self) -> int:
        """Its length, the line break included (not stored: a slot a line is a hundredth of a check's memory)."""
        return len(self.text)

    @property
    def content_end(self) -> int:
        """Where its line break starts: its length when it has none."""
        return _content_end(self.text)

    @property
    def texts(self) -> tuple[str, ...]:
        """The text of each significant token, interned: trees keep them, and names and keywords recur."""
        text = self.text
        return tuple([intern(text[start:end]) for start, end in zip(self.starts, self.ends, strict=True)])

    def tokens(self, offset: int = 0) -> list[Token]:
        """Every token of the line, trivia included, at ``offset`` in the source."""
        new = tuple.__new__  # builds the named tuple without its Python-level constructor
        text = self.text
        content_end = _content_end(text)
        tokens: list[Token] = []
        position = 0
        for kind, start, end in zip(self.kinds, self.starts, self.ends, strict=True):
            if start > position:
                tokens.append(new(Token, (_WS, text[position:start], position + offset)))
            tokens.append(new(Token, (kind, text[start:end], start + offset)))
            position = end
        end = self.comment_start if self.comment_start >= 0 else content_end
        if end > position:
            tokens.append(new(Token, (_WS, text[position:end], position + offset)))
        if self.comment_start >= 0:
            tokens.append(new(Token, (_COMMENT, text[self.comment_start : content_end], self.comment_start + offset)))
        if content_end < len(text):
            tokens.append(new(Token, (_NEWLINE, text[content_end:], content_end + offset)))
        return tokens


# MintMT's two-word closers: "End" and the block's word make one token of the kind the grammar knows.
_MINTMT_CLOSERS = {"IF": _K.ENDIF, "LOOP": _K.ENDL, "EVENT": _K.ENDEVENT, "STARTUP": _K.ENDSTARTUP}
_CLOSER_WORD = re.compile(r"[ \t]+([A-Za-z]+)\b")


def _mintmt_closer(line: str, end: int, content_end: int) -> tuple[TokenKind, int] | None:
    """The closer ``End <word>`` makes when ``End`` (ending at ``end``) is followed by a block's word."""
    found = _CLOSER_WORD.match(line, end, content_end)
    if found is None:
        return None
    kind = _MINTMT_CLOSERS.get(found[1].upper())
    return (kind, found.end()) if kind is not None else None


_EXPONENT = re.compile(r"([0-9]+)[eE]([0-9]+)")
_LARGEST_WHOLE = 16777215  # the largest integer a Mint number holds exactly (000:717-718)


def _with_an_exponent(text: str, mantissa: int, exponent: int) -> str:
    """``1E3``: Mint has no exponent notation (000:799-800); the number written out, where Mint holds it whole."""
    told = f"'{text}' is not a valid number: Mint numbers have no exponent"
    value = mantissa * 10**exponent if exponent <= len(str(_LARGEST_WHOLE)) else None
    return told if value is None or value > _LARGEST_WHOLE else f"{told}, write {value}"


def _number_issue(text: str, dialect: Dialect) -> str | None:
    """Why a number lexeme is not a valid Mint number, or None when it is."""
    if text[:2] in ("0x", "0X"):
        if dialect is Dialect.V3:
            return "hexadecimal numbers need Mint v4"
        digits = text[2:].replace("_", "")
        if not digits or any(c not in "0123456789abcdefABCDEF" for c in digits):
            return f"'{text}' is not a valid hexadecimal number"
        return None
    integer, _, fraction = text.partition(".")
    if (exponent := _EXPONENT.fullmatch(integer)) is not None:  # numbers are decimal, binary or hexadecimal
        return _with_an_exponent(text, int(exponent[1]), int(exponent[2]))
    if not integer.replace("_", "").isdigit() and integer:
        return f"'{text}' is not a valid number"
    if not fraction.isdigit() and fraction:
        return f"'{text}' is not a valid number"
    if "_" in integer:
        if dialect is Dialect.V3:
            return "digit separators need Mint v4"
        if not (integer.startswith("0") and "." not in text):
            return "'_' separates digits only in binary and hexadecimal numbers"
    binary = len(integer) > 1 and integer.startswith("0") and "." not in text
    if binary and any(c not in "01_" for c in integer):
        return f"'{text}' is not a valid binary number (a leading zero makes a number binary)"
    return None


# Beyond this many tokens a line is not analysed (the controller takes 255 characters a line):
# lexing the rest of a megabyte line would cost a hundred times its size in memory.
MAX_TOKENS = 20_000

# Kinds as module constants: reading an Enum member through its class costs a lookup in the
# metaclass, and the lexer reads them for every token.
_WS, _DOT, _NUMBER, _NAME, _COMMENT, _NEWLINE = _K.WS, _K.DOT, _K.NUMBER, _K.NAME, _K.COMMENT, _K.NEWLINE
_INVALID, _STRING, _CHAR, _LABEL, _HASH = _K.INVALID, _K.STRING, _K.CHAR, _K.LABEL, _K.HASH
_MINTMT, _V3 = Dialect.MINTMT, Dialect.V3  # read per line
_UNDERSCORE = "an underscore that begins a name must be followed by a letter or a digit"


# One tuple for each sequence of kinds, starts or ends that lines share: a program's lines
# take a few shapes (a tenth to a third as many as there are distinct lines).
_shapes: dict[tuple[object, ...], tuple[object, ...]] = {}
_SHAPES_KEPT = 200_000


def _shared(shape: tuple[T, ...]) -> tuple[T, ...]:
    """``shape``, or the equal tuple another line already holds."""
    if len(_shapes) >= _SHAPES_KEPT:
        _shapes.clear()
    return _shapes.setdefault(shape, shape)  # type: ignore[return-value]


# The kind of each user word lexed so far, per dialect: a program writes its names on many lines, and
# working out that a word ending in digits is no keyword with a glued channel (IN3) cost a microsecond.
_unlisted: dict[Dialect, dict[str, TokenKind]] = {dialect: {} for dialect in Dialect}


def _classified(words: Vocabulary, upper: str) -> TokenKind:
    """``words.classify_unlisted(upper)``, remembered."""
    known = _unlisted[words.dialect]
    if len(known) >= _SHAPES_KEPT:
        known.clear()
    kind = known[upper] = words.classify_unlisted(upper)
    return kind


def _lex_line(line: str, dialect: Dialect, words: Vocabulary) -> LexedLine:
    issues: list[Diagnostic] = []
    kinds: list[TokenKind] = []  # the significant tokens, as parallel arrays
    starts: list[int] = []
    ends: list[int] = []
    spellings = words.words
    unlisted = _unlisted[dialect]
    match = _LEXEME.match
    position = 0
    content_end = _code_end(line, _content_end(line))
    previous = _NEWLINE  # kind of the previous token, whitespace included
    dot_number = False  # the previous token is the number of a dot parameter: ".2" in REMOTEIN.2.65
    comment_start = -1
    mintmt = dialect is _MINTMT
    v3 = dialect is _V3

    while position < content_end:
        if len(kinds) == MAX_TOKENS:  # the rest is one token: a line this long is not analysed (grammar)
            kinds.append(_INVALID)
            starts.append(position)
            ends.append(content_end)
            break
        found = match(line, position, content_end)  # the alternatives cover every character
        group = found.lastgroup  # type: ignore[union-attr]
        if group is None:  # blanks to the end of the line
            break
        text = found[group]  # type: ignore[index]
        start = found.end() - len(text)  # type: ignore[union-attr]
        if start != position:  # blanks before it
            previous = _WS
            dot_number = False
            position = start
        # Only a number (.5) or a punctuation mark starts with ".", and only a character constant with a quote.
        if group == "word":
            upper = text.upper()
            if upper == "REM":
                comment_start = position
                break
            kind = spellings.get(upper) or unlisted.get(upper) or _classified(words, upper)
            end = found.end()  # type: ignore[union-attr]
            if v3 and not kinds and text == "PROTECT" and (password := _V3_PASSWORD.match(line, end, content_end)):
                kinds += (kind, _NAME)
                starts += (position, password.start(1))
                ends += (end, password.end(1))
                break
            if kind is _INVALID:
                issues.append(_syntax_issue(position, len(text), f"{text!r} is not a valid name: {_UNDERSCORE}"))
            if mintmt and kind is _K.END and (closer := _mintmt_closer(line, end, content_end)):
                kind, text = closer[0], line[position : closer[1]]
        elif text[0] == "." and (previous in _DOT_OWNERS or dot_number):
            kind, text = _DOT, "."
        elif group == "punct":
            if v3 and text in ("<", ">") and (spaced := _SPACED_RELATION.match(line, position, content_end)):
                text = spaced[0]
                kind = _PUNCTUATION[text[0] + text[-1]]
            else:
                kind = _PUNCTUATION[text]
            if mintmt and kind is _K.LPAR and kinds and kinds[-1] is _K.KEYWORD:
                kind = _K.ADDRESS
        elif group == "number":
            if previous is _DOT:  # a dot parameter: digits only, "2.65" is ".2" then ".65"
                text = _DIGITS_AFTER_DOT.match(line, position, content_end).group()  # type: ignore[union-attr]
            if text.isdigit() and (text[0] != "0" or len(text) == 1) and len(text) < _SHORTEST_TOO_LARGE_DECIMAL:
                kind = _NUMBER  # the common case: a plain decimal integer
            else:
                problem = _number_issue(text, dialect)
                kind = _NUMBER if problem is None else _INVALID
                if problem is not None:
                    issues.append(_syntax_issue(position, len(text), problem))
                elif len(text) >= SHORTEST_TOO_LARGE and dialect.modern and _too_large(text):
                    detail = f"{quoted(text)} is too large for a Mint number"
                    issues.append(mint_error(3, Span(position, position + len(text)), detail))
        elif group == "string":
            kind = _STRING
            issues.extend(_string_issues(text, position))
        elif group == "char":
            if mintmt:  # MintMT has no character constants: ' is its REM
                comment_start = position
                break
            if len(text) == 3:
                kind = _CHAR
                issues.extend(_quote_issues(text, position, _TYPOGRAPHIC_APOSTROPHES, "'"))
            else:
                kind = _INVALID
                detail = "a character constant is one character in single quotes"
                issues.append(_syntax_issue(position, len(text), detail))
        elif group == "hash":
            if not kinds and len(text) > 1:
                kind = _LABEL
            else:
                kind, text = _HASH, "#"
        else:
            kind = _INVALID
            issues.append(_syntax_issue(position, len(text), _unexpected(text, previous)))
        kinds.append(kind)
        starts.append(position)
        position += len(text)
        ends.append(position)
        dot_number = kind is _NUMBER and previous is _DOT
        previous = kind

    if mintmt and kinds and kinds[-1] is _K.THEN and _K.IF in kinds:
        kinds[-1] = _K.DO  # a Then that ends its line opens a block, as DO does in v4

    return LexedLine(
        line,
        tuple(issues),
        _shared(tuple(kinds)),
        _shared(tuple(starts)),
        _shared(tuple(ends)),
        comment_start,
    )


def _content_end(line: str) -> int:
    """Where the line break of ``line`` starts."""
    return len(line) - (2 if line.endswith("\r\n") else 1 if line.endswith(("\n", "\r")) else 0)


def comment_at(text: str, at: int) -> bool:
    """Whether a comment starts at ``at``: a REM as a word of its own (``remainder`` is a name) or MintMT's ``'``."""
    if text.startswith("'", at):
        return True
    follows = text[at + 3 : at + 4]
    return text[at : at + 3].upper() == "REM" and not (follows.isalnum() or follows == "_")


def _code_end(line: str, content_end: int) -> int:
    """Where the code of ``line`` ends: before the Ctrl-Z run that ends the file, when it is the file's last
    line (the only one with no line break), which is blanks to its end rather than unexpected characters."""
    return len(line) - len(end_of_file_mark(line)) if content_end == len(line) else content_end


# A Mint v4 number is binary32 (000:714-716), at most about 3.4E+38: 39 decimal digits, or 0x and 32 hex
# digits. A shorter literal is never too large, and only a v4 or MintMT reading looks (v3's numbers differ).
_SHORTEST_TOO_LARGE_DECIMAL, SHORTEST_TOO_LARGE = 39, 34


def _too_large(text: str) -> bool:
    """Whether the valid literal ``text`` is beyond the controller's numbers: mint-run stops on it with error 3."""
    return not binary32.holds(number_value(text))


def _unexpected(text: str, previous: TokenKind) -> str:
    """Why characters Mint has no use for are an error: other BASICs' string variable, ``a$`` (``previous``, the
    kind just before, blanks included, is the name's), told that Mint has none (000:929)."""
    if text[0] == "$" and previous is _NAME:
        return "'$' after a name: Mint has no string variables, a variable holds a number"
    return f"unexpected character {_shown(text[0])}"


def _shown(character: str) -> str:
    """A character in quotes as typed (repr would double a backslash); one that would not show, escaped."""
    return f"'{character}'" if character.isprintable() else repr(character)


def _syntax_issue(start: int, length: int, message: str) -> Diagnostic:
    return mint_error(2003, Span(start, start + length), message)


def _string_issues(text: str, start: int) -> list[Diagnostic]:
    issues: list[Diagnostic] = []
    closed = len(text) > 1 and text[-1] in '"' + _TYPOGRAPHIC_QUOTES
    if not closed:
        issues.append(_syntax_issue(start, len(text), "string is not closed before the end of the line"))
    issues.extend(_quote_issues(text, start, _TYPOGRAPHIC_QUOTES, '"'))
    return issues


def _quote_issues(text: str, start: int, typographic: str, plain: str) -> list[Diagnostic]:
    """A warning with a fix when a literal is delimited by word-processor quotes."""
    places = [i for i in (0, len(text) - 1) if text[i] in typographic]
    if not places:
        return []
    edits = tuple(Edit(Span(start + i, start + i + 1), plain) for i in sorted(set(places)))
    detail = f"typographic quotes: the controller expects plain quotes ({plain})"
    return [
        own("W101", Span(start, start + len(text)), detail, fixes=(Fix("Replace with plain quotes", edits, safe=True),))
    ]


# Per dialect, by the line's text: the key is the text the LexedLine holds anyway.
_lexed: dict[Dialect, RecentCache[str, LexedLine]] = {dialect: RecentCache(LINES_KEPT) for dialect in Dialect}


def remember(dialect: Dialect, line: LexedLine) -> None:
    """Take ``line`` for what lexing its text as ``dialect`` gives, unless the cache holds that text
    already: for a caller that knows ``dialect`` lexes it alike (``mintlang.syntax.alike``)."""
    cache = _lexed[dialect]
    if cache.get(line.text) is None:
        cache.put(line.text, line)


def clear_cache() -> None:
    for lines in _lexed.values():
        lines.clear()
    for known in _unlisted.values():
        known.clear()
    _shapes.clear()


class TokenStream(Sequence[Token]):
    """All tokens of a source with absolute offsets, made on first use.

    Checking a file needs only the significant tokens of each line; the full
    lossless stream (trivia included) is for the tools that rewrite or colour
    text, so it is built from the per-line results when first asked for.
    """

    __slots__ = ("_lines", "_tokens")

    def __init__(self, lines: PhysicalLines) -> None:
        self._lines = lines
        self._tokens: tuple[Token, ...] | None = None

    def _all(self) -> tuple[Token, ...]:
        if self._tokens is None:
            self._tokens = tuple(token for offset, line in self._lines for token in line.tokens(offset))
        return self._tokens

    def __len__(self) -> int:
        return len(self._all())

    @overload
    def __getitem__(self, index: int) -> Token: ...
    @overload
    def __getitem__(self, index: slice) -> Sequence[Token]: ...
    def __getitem__(self, index: int | slice) -> Token | Sequence[Token]:
        return self._all()[index]

    def __iter__(self) -> Iterator[Token]:
        return iter(self._all())

    def __repr__(self) -> str:
        return f"TokenStream({len(self)} tokens)"


class PhysicalLines(Sequence[tuple[int, LexedLine]]):
    """Every physical line of a source, lexed, with its offset: ``(offset, line)`` pairs, made when read.

    The offsets are machine integers in one array and the lines one tuple: a pair and an int
    object per line took a twentieth of a check's memory on a file of short lines. After an edit
    both are pieces of the versions before (``MovedOffsets``, ``Spliced``): a keystroke copies neither.
    """

    __slots__ = ("_lines", "offsets")

    def __init__(self, offsets: Sequence[int], lines: Sequence[LexedLine]) -> None:
        self.offsets = offsets  # ascending: ``bisect`` finds the line of an offset
        self._lines = lines

    def __len__(self) -> int:
        return len(self._lines)

    @overload
    def __getitem__(self, index: int) -> tuple[int, LexedLine]: ...
    @overload
    def __getitem__(self, index: slice) -> Sequence[tuple[int, LexedLine]]: ...
    def __getitem__(self, index: int | slice) -> tuple[int, LexedLine] | Sequence[tuple[int, LexedLine]]:
        if isinstance(index, slice):
            return list(zip(self.offsets[index], self._lines[index], strict=True))
        return self.offsets[index], self._lines[index]

    def __iter__(self) -> Iterator[tuple[int, LexedLine]]:
        return zip(self.offsets, self._lines, strict=True)

    def lexed(self, index: int) -> LexedLine:
        return self._lines[index]

    def spliced(self, first: int, end: int, offsets: array[int], lines: list[LexedLine], shift: int) -> PhysicalLines:
        """These lines with ``first`` to ``end`` replaced by ``lines`` at ``offsets``, and the lines
        after them ``shift`` characters further on: what an edit to those lines makes of the file."""
        moved = MovedOffsets.spliced(self.offsets, (first, end), offsets, shift, 0)
        return PhysicalLines(moved, Spliced.spliced(self._lines, (first, end), lines, 0, 0))


@record
class LexResult:
    tokens: TokenStream
    issues: tuple[Diagnostic, ...]
    lines: PhysicalLines  # each physical line with its offset


def lex(source: str, dialect: Dialect = Dialect.V4) -> LexResult:
    """Split ``source`` into tokens whose texts join back to ``source`` exactly."""
    offsets: array[int] = array("q")
    lines: list[LexedLine] = []
    issues: list[Diagnostic] = []
    lex_lines(source, dialect, 0, offsets, lines, issues)
    physical = PhysicalLines(offsets, tuple(lines))
    return LexResult(TokenStream(physical), tuple(issues), physical)


def lex_lines(  # noqa: PLR0917 - the text, where it starts, and the three lists it extends
    text: str, dialect: Dialect, start: int, offsets: array[int], lines: list[LexedLine], issues: list[Diagnostic]
) -> None:
    """Lex the physical lines of ``text``, which starts at offset ``start`` of its file: a whole file,
    or the lines an edit touched (``mintlang.syntax.reparse``)."""
    offset = start
    cache, words = _lexed[dialect], vocabulary(dialect)
    for physical in _LINE.findall(text):
        if not physical:
            continue
        lexed = cache.get(physical)
        if lexed is None:
            lexed = _lex_line(physical, dialect, words)
            cache.put(physical, lexed)
        offsets.append(offset)
        lines.append(lexed)
        if lexed.issues:
            issues.extend(issue.shifted(offset) for issue in lexed.issues)
        offset += len(physical)
