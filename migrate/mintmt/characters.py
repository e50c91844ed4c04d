"""``'A'`` becomes ``65``: MintMT has no character constants, its ``'`` starts a comment (MT-8).

A v4 character constant stands for the code of its upper case (v4 guide 3.2.3), so
the number is the same value. A quote v4 itself cannot read (``'ab'``) would also
turn the rest of its line into a comment in MintMT: it is flagged, not rewritten.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.migrate.mintmt.source import Action, Flag, Rewrite, Source, span
from mintlang.syntax.nodes import character_code
from mintlang.syntax.tokens import TokenKind

ID = "MT-CHARACTER"
SUMMARY = "character constants become their codes; a stray quote is flagged"

_QUOTES = "'\u2018\u2019"


def find(source: Source) -> Iterator[Action]:
    for _, _, token in source.tokens():
        if token.kind is TokenKind.CHAR:
            yield Rewrite(ID, span(token), str(character_code(token.text)))
        elif token.kind is TokenKind.INVALID and token.text[0] in _QUOTES:
            reason = f"{token.text} is no character constant: MintMT would read the rest of the line as a comment"
            yield Flag(ID, token.start, reason)
