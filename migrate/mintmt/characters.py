"""``'A'`` becomes ``65``: MintMT has no character constants, its ``'`` starts a comment (MT-8).

A v4 character constant stands for the code of its upper case (v4 guide 3.2.3), so
the number is the same value. (A quote v4 itself cannot read, ``'ab'``, makes the
text MintMT already: ``api`` leaves it as it is.)
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.migrate.mintmt.source import Action, Rewrite, Source, span
from mintlang.syntax.nodes import character_code
from mintlang.syntax.tokens import TokenKind

ID = "MT-CHARACTER"
SUMMARY = "character constants become their codes"


def find(source: Source) -> Iterator[Action]:
    for _, _, token in source.tokens():
        if token.kind is TokenKind.CHAR:
            yield Rewrite(ID, span(token), str(character_code(token.text)))
