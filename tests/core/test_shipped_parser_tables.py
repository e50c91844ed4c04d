"""The package ships its parsers' LALR tables, so a start-up loads them instead of computing them.

When grammar.lark changes, ``python -m tools.lalr_tables`` writes them again;
until it is run, the tables no longer match and every start would pay for
computing them, which this test catches.
"""

from __future__ import annotations

import pytest
from lark import Lark, Token
from lark.exceptions import UnexpectedInput

from mintlang.dialect import Dialect
from mintlang.syntax.grammar import build_parser, fingerprint, shipped_tables
from mintlang.syntax.lexer import lex
from mintlang.syntax.lines import logical_lines
from mintlang.syntax.tokens import TokenKind
from tests.corpus_files import CORPUS


@pytest.mark.parametrize("dialect", list(Dialect))
def test_the_shipped_tables_were_made_from_the_current_grammar(dialect: Dialect) -> None:
    made_from, _ = shipped_tables(dialect)
    assert made_from.split()[0] == fingerprint(dialect).split()[0], (
        "grammar.lark changed: run python -m tools.lalr_tables"
    )


@pytest.mark.parametrize("dialect", list(Dialect))
def test_the_shipped_parser_parses_the_corpus_as_one_built_from_the_grammar(dialect: Dialect) -> None:
    _, tables = shipped_tables(dialect)
    shipped = Lark.load(tables)
    built = build_parser(dialect)
    sequences = {
        tuple(line.tokens().kinds)
        for path in sorted(CORPUS.rglob("*.mnt"))
        for line in logical_lines(lex(path.read_text(encoding="utf-8"), dialect))
    }
    assert len(sequences) > 500
    for kinds in sequences:
        assert _outcome(shipped, kinds) == _outcome(built, kinds), kinds


def _outcome(parser: Lark, kinds: tuple[TokenKind, ...]) -> str:
    stream = [Token(kind.value, kind.value, start_pos=index, end_pos=index) for index, kind in enumerate(kinds)]
    try:
        return parser.parse(stream).pretty()  # type: ignore[arg-type]
    except UnexpectedInput as error:
        return f"rejected at {getattr(error, 'token', None)!r}"
