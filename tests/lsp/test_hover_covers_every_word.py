"""Every word the lexer reads as a keyword, a constant or a reserved word has a hover, in each dialect: a word
the compiler knows and the editor says nothing about is a gap (NULL and v3's _limit had none)."""

from __future__ import annotations

import pytest

from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.lsp.features.hover import hover_text
from mintlang.lsp.workspace import Analyses, Settings
from mintlang.syntax.tokens import TRIVIA, TokenKind

_NAMES = frozenset({TokenKind.NAME, TokenKind.LABEL, TokenKind.NUMBER, TokenKind.INVALID})


def _words(dialect: Dialect) -> list[str]:
    """The dialect's keywords and constants, and NULL, the reserved word CAMTABLE takes (000:7958)."""
    db = database()
    if dialect is Dialect.V3:
        names = [*db.v3_keywords, *(constant.name for constant in db.v3_constants.values())]
    else:
        names = [*db.keywords_of(dialect), *(constant.name for constant in db.constants_of(dialect).values())]
    return sorted({name for name in names if name[:1].isalpha() or name[:1] == "_"} | {"NULL"})


@pytest.mark.parametrize("dialect", list(Dialect), ids=str)
def test_every_keyword_and_constant_has_a_hover(dialect: Dialect) -> None:
    words = _words(dialect)
    text = "".join(f"{word}\n" for word in words)
    analyses = Analyses(read=lambda _: None, settings=Settings.from_options({"dialect": dialect.value}))
    snapshot = analyses.snapshot(f"file:///words_{dialect.value}.mnt", text, 1)
    silent = []
    for token in snapshot.document.tokens:
        if token.kind not in TRIVIA and token.kind not in _NAMES and hover_text(snapshot, token.start) is None:
            silent.append(token.text)
    assert silent == []
