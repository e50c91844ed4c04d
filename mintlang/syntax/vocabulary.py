"""What each word means to the lexer, per dialect.

Mint words are case-insensitive and keywords may be abbreviated, so the lexer
needs one table from every spelling (upper-cased) to its token kind. The table
is derived from the keyword database once per dialect (and controller: an
abbreviation the guide gives to two keywords names the one the controller has,
while its token kind is the same on every controller, so lexing needs none).
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import cache

from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Controller, KeywordKind, Spelling, V3Keyword
from mintlang.records import record
from mintlang.syntax.tokens import GRAMMAR_KEYWORDS, TokenKind

_MINTMT_BLOCK_WORDS = (TokenKind.EVENT, TokenKind.STARTUP)  # their closers are two words: the lexer's

_ROLES: Mapping[str, TokenKind] = {kind.value: kind for kind in GRAMMAR_KEYWORDS}


@record
class Vocabulary:
    """Spelling tables of one dialect."""

    dialect: Dialect
    words: Mapping[str, TokenKind]  # upper-case spelling -> kind (names and abbreviations)
    canonical: Mapping[str, str]  # upper-case spelling -> the keyword's full name
    suffixed: frozenset[str]  # spellings that also take a glued channel number: IN3, OUT1 (v4 also OT1)
    constants: frozenset[str]  # upper-case names of predefined constants
    indices: Mapping[str, int]  # MintMT: how many of a keyword's bracketed items follow its axes

    def classify_unlisted(self, upper: str) -> TokenKind:
        """The kind of an upper-case word that is no keyword spelling: constant, IN3-style, a name, or
        invalid (``_``, ``__x``)."""
        if upper[0] == "_":
            if upper in self.constants:
                return TokenKind.CONSTANT
            # A name begins with _ only when a letter or digit follows it (000:882-884, 001:1342).
            bad = (len(upper) == 1 or upper[1] == "_") and self.dialect is not Dialect.MINTMT
            return TokenKind.INVALID if bad else TokenKind.NAME
        if upper[-1].isdigit() and self.split_channel(upper) is not None:
            return TokenKind.KEYWORD
        return TokenKind.NAME

    def split_channel(self, word: str) -> tuple[str, int] | None:
        """``IN12`` -> ``("IN", 12)`` when IN takes a glued channel number."""
        upper = word.upper()
        stem = upper.rstrip("0123456789")
        if stem == upper or stem not in self.suffixed:
            return None
        return self.canonical[stem], int(upper[len(stem) :])

    def quoted(self, word: str) -> str:
        """``word`` quoted for a message that calls it Mint's own, saying which keyword an abbreviation
        stands for: a user who writes ``DIM spd`` has no reason to know that SPD is SPEEDDEMAND."""
        upper = word.upper()
        name = self.canonical.get(upper)
        if name is None and (split := self.split_channel(upper)) is not None:
            name = f"{split[0]}{split[1]}"  # OT2: output 2, OUT2
        return f"'{word}' (short for {name})" if name is not None and name != upper else f"'{word}'"

    def keyword_name(self, word: str) -> str | None:
        """Full keyword name for a spelling, abbreviation or channel-suffixed form."""
        upper = word.upper()
        name = self.canonical.get(upper)
        if name is not None:
            return name
        split = self.split_channel(upper)
        return split[0] if split else None


def _kind_of(name: str, kind: KeywordKind, has_parameters: bool) -> TokenKind:
    role = _ROLES.get(name)
    if role is not None:
        return role
    if has_parameters or kind is KeywordKind.FUNCTION:
        return TokenKind.FUNCTION
    return TokenKind.KEYWORD


def _v3_kind_of(keyword: V3Keyword) -> TokenKind:
    """The kind of a v3 keyword no v4 keyword shares a name with (PEEK, XIO, HMSPEED)."""
    if keyword.function:
        return TokenKind.FUNCTION
    return _ROLES.get(keyword.name, TokenKind.KEYWORD)


@cache
def _spelled(dialect: Dialect) -> tuple[tuple[Spelling, TokenKind], ...]:
    """How each keyword of a v4-based dialect is written, with its token kind: the same on every controller,
    so read once for the lexer's vocabulary and the parser's (of the controller) alike."""
    # Spellings, not keywords: building every keyword's record was a tenth of a one-line check.
    spellings = (spelling for spelling in database().spellings_of(dialect) if spelling.kind is not KeywordKind.EVENT)
    return tuple((spelling, _kind_of(spelling.name, spelling.kind, spelling.takes_arguments)) for spelling in spellings)


@cache
def vocabulary(dialect: Dialect, controller: Controller | None = None) -> Vocabulary:
    """The spelling tables of ``dialect`` on ``controller`` (any, when None), built once per process."""
    db = database()
    words: dict[str, TokenKind] = {}
    canonical: dict[str, str] = {}
    suffixed: set[str] = set()

    def add(spelling: str, name: str, kind: TokenKind) -> None:
        upper = spelling.upper()
        if upper.replace("_", "").isalnum() and upper not in words:
            words[upper] = kind
            canonical[upper] = name

    indices: dict[str, int] = {}
    if dialect.modern:
        spelled = _spelled(dialect)
        for spelling, kind in spelled:
            add(spelling.name, spelling.name, kind)
            if spelling.channel_suffix:
                suffixed.add(spelling.name)
            if spelling.indices:
                indices[spelling.name] = spelling.indices
        for spelling, kind in spelled:
            for abbreviation in spelling.abbreviations:
                if db.owner(abbreviation, controller) == spelling.name:  # a shared one goes to one keyword
                    add(abbreviation, spelling.name, kind)
                    if spelling.channel_suffix:  # an abbreviation stands for the name: OT2 is OUT2
                        suffixed.add(abbreviation.upper())
        constants = frozenset(db.constants_of(dialect))
        if dialect is Dialect.MINTMT:
            for word in _MINTMT_BLOCK_WORDS:
                add(word.value, word.value, word)
    else:
        for v3 in db.v3_keywords.values():
            v4 = db.keywords.get(v3.name)
            kind = _kind_of(v3.name, v4.kind, bool(v4.parameters)) if v4 else _v3_kind_of(v3)
            add(v3.name, v3.name, kind)
            for abbreviation in v3.abbreviations:
                add(abbreviation, v3.name, kind)
            if v4 is not None and v4.channel_suffix:
                suffixed.add(v3.name)
        constants = frozenset(db.v3_constants)
    # CAMTABLE's "no table" argument: a reserved word, not a keyword entry (v4 guide line 7958).
    words.setdefault("NULL", TokenKind.CONSTANT)
    return Vocabulary(dialect, words, canonical, frozenset(suffixed), constants, indices)
