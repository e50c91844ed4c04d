"""The lossless, line-oriented Mint lexer.

One compiled regular expression finds the next lexeme; a little state decides
what it means where Mint's grammar depends on position:

* ``#name`` is a label only as the first non-blank of a line (else ``#`` selects a terminal);
* ``.`` right after a keyword is the dot parameter (``SPEED.1``), elsewhere it starts a number (``.5``);
* ``REM`` comments the rest of the line; ``IN3`` is keyword IN with channel 3;
* a number with a leading zero is binary (``011011``), so ``05`` is invalid.

Lexing a line depends only on the line's text, so results are cached per line:
programs repeat lines (``GO``, ``PAUSE IDLE``, ``RETURN``) and the language
server re-lexes on every keystroke.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass
from functools import lru_cache

from mintlang.codes import mint_error, own
from mintlang.diagnostics import Diagnostic, Edit, Fix, Span
from mintlang.dialect import Dialect
from mintlang.syntax.tokens import TRIVIA, Token, TokenKind
from mintlang.syntax.vocabulary import Vocabulary, vocabulary

_K = TokenKind

_SPACE = " \t\f\v\u00a0\ufeff"
_TYPOGRAPHIC_QUOTES = "\u201c\u201d\u201e\u201f\u2033"
_TYPOGRAPHIC_APOSTROPHES = "\u2018\u2019"
_DOUBLE = '"' + _TYPOGRAPHIC_QUOTES
_SINGLE = "'" + _TYPOGRAPHIC_APOSTROPHES
_LEXEME = re.compile(
    "|".join(
        (
            f"(?P<ws>[{_SPACE}]+)",
            r"(?P<word>[A-Za-z_][A-Za-z0-9_]*)",
            r"(?P<number>0[xX][0-9A-Za-z_]*|[0-9][0-9A-Za-z_]*(?:\.[0-9]*)?|\.[0-9]+)",
            f"(?P<string>[{_DOUBLE}][^{_DOUBLE}\r\n]*[{_DOUBLE}]?)",
            f"(?P<char>[{_SINGLE}][^{_SINGLE}\r\n]?[{_SINGLE}]?)",
            r"(?P<hash>\#[A-Za-z0-9_]*)",
            r"(?P<punct><>|<=|>=|[-<>=+*/%&|!~^()\[\],;:?.])",
            f"(?P<invalid>[^{_SPACE}\r\nA-Za-z0-9_{_DOUBLE}{_SINGLE}#<>=+*/%&|!~^()\\[\\],;:?.\\-]+)",
        )
    )
)
_LINE = re.compile(r"[^\r\n]*(?:\r\n|\r|\n)?")
_DIGITS_AFTER_DOT = re.compile(r"[0-9]+")

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


@dataclass(frozen=True, slots=True)
class LexedLine:
    """One physical line, lexed: offsets are relative to the line's start.

    Besides all its tokens, it keeps the significant ones as parallel arrays,
    which is the form the parser consumes.
    """

    tokens: tuple[Token, ...]
    issues: tuple[Diagnostic, ...]
    kinds: tuple[TokenKind, ...]  # significant tokens only
    texts: tuple[str, ...]
    starts: tuple[int, ...]
    ends: tuple[int, ...]
    comment_end: int  # end of a REM comment, or 0: comments belong to the line's span
    length: int  # including the line break


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


def _lex_line(line: str, dialect: Dialect, words: Vocabulary) -> LexedLine:
    tokens: list[Token] = []
    issues: list[Diagnostic] = []
    append = tokens.append
    classify = words.classify
    match = _LEXEME.match
    new = tuple.__new__  # builds the named tuple without its Python-level constructor
    position = 0
    length = len(line)
    content_end = length - (2 if line.endswith("\r\n") else 1 if line.endswith(("\n", "\r")) else 0)
    line_start = True  # no significant token yet on this line
    previous = _K.NEWLINE
    dot_number = False  # the previous token is the number of a dot parameter: ".2" in REMOTEIN.2.65

    while position < content_end:
        found = match(line, position, content_end)
        assert found is not None  # the alternatives cover every character
        group = found.lastgroup
        text = found.group()
        kind: TokenKind
        if text[0] == "." and (previous in _DOT_OWNERS or dot_number):
            append(Token(_K.DOT, ".", position))
            previous = _K.DOT
            position += 1
            line_start = False
            continue
        if group == "ws":
            append(new(Token, (_K.WS, text, position)))
            previous = _K.WS
            dot_number = False
            position = found.end()
            continue
        if group == "word":
            if text.upper() == "REM":
                append(Token(_K.COMMENT, line[position:content_end], position))
                position = content_end
                break
            kind = classify(text)
        elif group == "number":
            if previous is _K.DOT:
                digits = _DIGITS_AFTER_DOT.match(line, position, content_end)
                if digits is not None:
                    text = digits.group()
            problem = _number_issue(text, dialect) if previous is not _K.DOT else None
            if problem is not None:
                kind = _K.INVALID
                issues.append(_syntax_issue(position, len(text), problem))
            else:
                kind = _K.NUMBER
        elif group == "punct":
            kind = _PUNCTUATION[text]
        elif group == "string":
            kind = _K.STRING
            issues.extend(_string_issues(text, position))
        elif group == "char":
            if len(text) == 3:
                kind = _K.CHAR
                issues.extend(_quote_issues(text, position, _TYPOGRAPHIC_APOSTROPHES, "'"))
            else:
                kind = _K.INVALID
                issues.append(
                    _syntax_issue(position, len(text), "a character constant is one character in single quotes")
                )
        elif group == "hash":
            if line_start and len(text) > 1:
                kind = _K.LABEL
            else:
                text = "#"
                kind = _K.HASH
        else:
            kind = _K.INVALID
            issues.append(_syntax_issue(position, len(text), f"unexpected character {text[0]!r}"))
        append(new(Token, (kind, text, position)))
        position += len(text)
        dot_number = kind is _K.NUMBER and previous is _K.DOT
        previous = kind
        line_start = False

    comment_end = 0
    if tokens and tokens[-1].kind is _K.COMMENT:
        comment_end = content_end
    if content_end < length:
        append(Token(_K.NEWLINE, line[content_end:], content_end))
    significant = [token for token in tokens if token.kind not in TRIVIA]
    return LexedLine(
        tuple(tokens),
        tuple(issues),
        tuple(token.kind for token in significant),
        tuple(token.text for token in significant),
        tuple(token.start for token in significant),
        tuple(token.start + len(token.text) for token in significant),
        comment_end,
        length,
    )


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
    return [own("W101", Span(start, start + len(text)), detail, fixes=(Fix("Replace with plain quotes", edits),))]


@lru_cache(maxsize=65536)
def _lex_line_cached(line: str, dialect: Dialect) -> LexedLine:
    return _lex_line(line, dialect, vocabulary(dialect))


def clear_cache() -> None:
    _lex_line_cached.cache_clear()


def _relocate(diagnostic: Diagnostic, offset: int) -> Diagnostic:
    span = Span(diagnostic.span.start + offset, diagnostic.span.end + offset)
    fixes = tuple(
        Fix(fix.title, tuple(Edit(Span(e.span.start + offset, e.span.end + offset), e.text) for e in fix.edits))
        for fix in diagnostic.fixes
    )
    return Diagnostic(diagnostic.code, diagnostic.severity, span, diagnostic.message, diagnostic.mint_error, fixes)


@dataclass(frozen=True, slots=True)
class LexResult:
    tokens: tuple[Token, ...]
    issues: tuple[Diagnostic, ...]
    lines: tuple[tuple[int, LexedLine], ...]  # each physical line with its offset


def lex(source: str, dialect: Dialect = Dialect.V4) -> LexResult:
    """Split ``source`` into tokens whose texts join back to ``source`` exactly."""
    tokens: list[Token] = []
    issues: list[Diagnostic] = []
    lines: list[tuple[int, LexedLine]] = []
    offset = 0
    lex_line: Callable[[str, Dialect], LexedLine] = _lex_line_cached
    new_token = tuple.__new__  # skips the named tuple's Python-level constructor
    for physical in _LINE.findall(source):
        if not physical:
            continue
        lexed = lex_line(physical, dialect)
        lines.append((offset, lexed))
        if offset:
            tokens.extend([new_token(Token, (t[0], t[1], t[2] + offset)) for t in lexed.tokens])
            issues.extend(_relocate(issue, offset) for issue in lexed.issues)
        else:
            tokens.extend(lexed.tokens)
            issues.extend(lexed.issues)
        offset += lexed.length
    return LexResult(tuple(tokens), tuple(issues), tuple(lines))
