"""A v4 name that MintMT makes a word of its own (``TRIGGERMODE``, ``Event``, ``Startup`` …) is flagged.

MintMT adds keywords and block words to v4's (MT-1): a variable, array or macro so
called in v4 would be read as the keyword. Renaming it is a choice for a person
(the new name must be free in the whole application), so every line using it is
flagged and nothing is rewritten.
"""

from __future__ import annotations

from collections.abc import Iterator
from functools import cache

from mintlang.dialect import Dialect
from mintlang.migrate.mintmt.source import Action, Flag, Source
from mintlang.syntax.tokens import TokenKind
from mintlang.syntax.vocabulary import vocabulary

ID = "MT-NAME"
SUMMARY = "names that are MintMT keywords are flagged"


@cache
def _mintmt_words() -> frozenset[str]:
    """The upper-case words MintMT reads as keywords, constants or block words and v4 as names."""
    v4, mintmt = vocabulary(Dialect.V4), vocabulary(Dialect.MINTMT)
    return frozenset(word for word, kind in mintmt.words.items() if kind is not TokenKind.NAME and word not in v4.words)


def find(source: Source) -> Iterator[Action]:
    words = _mintmt_words()
    for _, _, token in source.tokens():
        if token.kind is TokenKind.NAME and token.text.upper() in words:
            reason = f"{token.text} is a MintMT keyword: rename it in the whole application"
            yield Flag(ID, token.start, reason)
