"""Token kinds and the token record shared by the lexer, parser and tools.

Every character of a source belongs to exactly one token, trivia included, so
``"".join(token.text for token in tokens) == source`` always holds. Tools that
rewrite code (the migrator, the formatter) edit token spans and never
regenerate text.
"""

from __future__ import annotations

from enum import StrEnum
from typing import NamedTuple

# DOS editors ended a file with Ctrl-Z, their end-of-file mark (the v3 guide has array files end with one,
# 001:1799): a run of it ending a file is no character of the program, though a tool keeps its bytes.
_END_OF_FILE = "\x1a"
# A UTF-8 file may start with a byte-order mark: no character of the program either, though a tool keeps it.
BYTE_ORDER_MARK = "\ufeff"


def end_of_file_mark(text: str) -> str:
    """The Ctrl-Z run ending ``text``, or "": the DOS end-of-file mark, no line of the program."""
    return text[len(text.rstrip(_END_OF_FILE)) :]


def in_a_word(character: str) -> bool:
    """Whether ``character`` can be part of a name, keyword or number (a letter, a digit or ``_``): where a word
    written in the text begins and ends, for tools that look at text rather than tokens."""
    return character.isalnum() or character == "_"


class TokenKind(StrEnum):
    """Lexical categories. Significant kinds double as the grammar's terminal names."""

    # Enum hashes members in Python; kinds are hashed in every hot loop, so use str's C hash.
    __hash__ = str.__hash__

    # Trivia: kept for losslessness, never seen by the grammar.
    WS = "WS"
    NEWLINE = "NEWLINE"
    COMMENT = "COMMENT"  # REM to the end of the line

    # Words and literals.
    NAME = "NAME"  # user variable, array, macro or label reference
    KEYWORD = "KEYWORD"  # any keyword without its own grammar role (SPEED, GO, IN1 ...)
    FUNCTION = "FUNCTION"  # keyword taking bracketed arguments (SIN, POW, COMMS ...)
    CONSTANT = "CONSTANT"  # predefined constant (_TRUE, _hmPOSITIVE_SWITCH ...)
    NUMBER = "NUMBER"
    CHAR = "CHAR"  # 'A'
    STRING = "STRING"
    LABEL = "LABEL"  # #name as the first non-blank of a line
    HASH = "HASH"  # # elsewhere: terminal selector of PRINT, INPUT ...
    MACRO_BODY = "MACRO_BODY"  # the raw text after DEFINE name =
    INVALID = "INVALID"  # characters or numbers the language does not accept

    # Keywords with their own grammar role (the text may be an abbreviation or symbol).
    IF = "IF"
    THEN = "THEN"
    DO = "DO"
    ELSE = "ELSE"
    ENDIF = "ENDIF"
    FOR = "FOR"
    TO = "TO"
    STEP = "STEP"
    NEXT = "NEXT"
    REPEAT = "REPEAT"
    UNTIL = "UNTIL"
    WHILE = "WHILE"
    ENDW = "ENDW"
    LOOP = "LOOP"
    ENDL = "ENDL"
    EXIT = "EXIT"
    GOSUB = "GOSUB"
    GOTO = "GOTO"
    RETURN = "RETURN"
    END = "END"
    PAUSE = "PAUSE"
    DIM = "DIM"
    DEFINE = "DEFINE"
    AXES = "AXES"
    PRINT = "PRINT"  # also ?
    INPUT = "INPUT"
    USING = "USING"
    HEX = "HEX"
    DEC = "DEC"
    BIN = "BIN"
    AND = "AND"  # also &
    OR = "OR"  # also |
    XOR = "XOR"
    NOT = "NOT"  # also !
    MOD = "MOD"  # also %

    # MintMT's blocks: "End Event" and "End Startup" are one token each, as are "End If"
    # (ENDIF) and "End Loop" (ENDL).
    EVENT = "EVENT"
    ENDEVENT = "ENDEVENT"
    STARTUP = "STARTUP"
    ENDSTARTUP = "ENDSTARTUP"

    # Punctuation.
    LPAR = "LPAR"
    RPAR = "RPAR"
    LSQB = "LSQB"
    RSQB = "RSQB"
    COMMA = "COMMA"
    SEMICOLON = "SEMICOLON"
    COLON = "COLON"
    EQUAL = "EQUAL"
    NOTEQUAL = "NOTEQUAL"
    LESSEQUAL = "LESSEQUAL"
    MOREEQUAL = "MOREEQUAL"
    LESSTHAN = "LESSTHAN"
    MORETHAN = "MORETHAN"
    PLUS = "PLUS"
    MINUS = "MINUS"
    STAR = "STAR"
    SLASH = "SLASH"
    TILDE = "TILDE"
    CIRCUMFLEX = "CIRCUMFLEX"
    DOT = "DOT"
    ADDRESS = "ADDRESS"  # MintMT: the "(" that opens a keyword's axes or channels, MOVER(0) = 10


TRIVIA = frozenset({TokenKind.WS, TokenKind.NEWLINE, TokenKind.COMMENT})

# Keywords that have their own role in the grammar.
GRAMMAR_KEYWORDS = frozenset(
    TokenKind(name)
    for name in (
        *("IF", "THEN", "DO", "ELSE", "ENDIF", "FOR", "TO", "STEP", "NEXT"),
        *("REPEAT", "UNTIL", "WHILE", "ENDW", "LOOP", "ENDL", "EXIT"),
        *("GOSUB", "GOTO", "RETURN", "END", "PAUSE", "DIM", "DEFINE", "AXES"),
        *("PRINT", "INPUT", "USING", "HEX", "DEC", "BIN", "AND", "OR", "XOR", "NOT", "MOD"),
    )
)

# MintMT's block words (mintlang/MINTMT.md).
MINTMT_BLOCK_WORDS = frozenset({TokenKind.EVENT, TokenKind.ENDEVENT, TokenKind.STARTUP, TokenKind.ENDSTARTUP})

# Every kind a word of letters can lex to.
WORDS = (
    frozenset({TokenKind.NAME, TokenKind.KEYWORD, TokenKind.FUNCTION, TokenKind.CONSTANT})
    | GRAMMAR_KEYWORDS
    | MINTMT_BLOCK_WORDS
)


class Token(NamedTuple):
    """One lexeme: its kind, its exact text and its offset in the source.

    A named tuple rather than a dataclass: tokens are the most numerous objects
    the toolchain creates, and tuple construction is several times cheaper.
    """

    kind: TokenKind
    text: str
    start: int

    @property
    def end(self) -> int:
        return self.start + len(self.text)
