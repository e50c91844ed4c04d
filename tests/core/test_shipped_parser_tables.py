"""The package ships its parsers' LALR tables and lark's stand-alone runtime, so a start-up loads
them instead of importing lark and computing the tables.

When grammar.lark changes or lark is upgraded, ``python -m tools.lalr_tables`` writes them again;
until it is run, these tests fail (and every start computes the tables with lark itself).
"""

from __future__ import annotations

from pathlib import Path

import lark
import pytest

from mintlang.dialect import Dialect
from mintlang.syntax import grammar, lark_runtime
from mintlang.syntax.grammars import grammar_text
from mintlang.syntax.lexer import lex
from mintlang.syntax.lines import logical_lines
from mintlang.syntax.tables import build_parser, runtime_source
from mintlang.syntax.tokens import TokenKind
from tests.corpus_files import CORPUS


@pytest.mark.parametrize("dialect", list(Dialect))
def test_the_shipped_tables_were_made_from_the_current_grammar(dialect: Dialect) -> None:
    assert grammar.shipped_tables(dialect)["grammar"] == grammar_text(dialect), (
        "grammar.lark changed: run python -m tools.lalr_tables"
    )


def test_the_shipped_runtime_is_what_the_installed_lark_generates() -> None:
    shipped = Path(lark_runtime.__file__).read_text(encoding="utf-8")
    assert shipped == runtime_source(), "lark was upgraded: run python -m tools.lalr_tables"
    assert {grammar.shipped_tables(dialect)["lark"] for dialect in Dialect} == {lark_runtime.__version__}


@pytest.mark.parametrize("dialect", list(Dialect))
def test_the_shipped_parser_parses_the_corpus_as_lark_built_from_the_grammar(dialect: Dialect) -> None:
    shipped = grammar.load_parser(grammar.shipped_tables(dialect)["parser"])
    built = build_parser(dialect)
    sequences = {
        tuple(line.tokens().kinds)
        for path in sorted(CORPUS.rglob("*.mnt"))
        for line in logical_lines(lex(path.read_text(encoding="utf-8"), dialect))
    }
    assert len(sequences) > 500
    for kinds in sequences:
        assert _outcome(shipped, kinds) == _outcome(built, kinds), kinds


def test_the_shipped_parser_decodes_a_state_of_its_table_when_a_parse_first_visits_it() -> None:
    shipped = grammar.shipped_tables(Dialect.V4)["parser"]
    parser = grammar.load_parser(shipped)
    states = parser.parser.parser._parse_table.states
    assert dict(states) == {}
    kinds = (TokenKind.KEYWORD, TokenKind.EQUAL, TokenKind.NUMBER)
    assert _outcome(parser, kinds) == _outcome(build_parser(Dialect.V4), kinds)
    assert 0 < len(states) < len(shipped["data"]["parser"]["parser"]["states"])


def test_a_grammar_edited_since_the_tables_were_written_is_parsed_with_tables_computed_now(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    shipped = grammar.shipped_tables(Dialect.V4)
    monkeypatch.setattr(grammar, "shipped_tables", lambda dialect: {**shipped, "grammar": "an older grammar"})
    grammar._parser.cache_clear()
    try:
        parser = grammar._parser(Dialect.V4)
    finally:
        grammar._parser.cache_clear()
    kinds = (TokenKind.KEYWORD, TokenKind.EQUAL, TokenKind.NUMBER)
    assert _outcome(parser, kinds) == _outcome(build_parser(Dialect.V4), kinds)


def _outcome(parser: lark.Lark | lark_runtime.Lark, kinds: tuple[TokenKind, ...]) -> str:
    """The tree of the parse, or the token it stopped at, in the token and error classes of the parser's lark."""
    own = lark_runtime if isinstance(parser, lark_runtime.Lark) else lark
    stream = [own.Token(kind.value, kind.value, start_pos=index, end_pos=index) for index, kind in enumerate(kinds)]
    try:
        return parser.parse(stream).pretty()  # type: ignore[arg-type]
    except own.UnexpectedInput as error:
        return f"rejected at {getattr(error, 'token', None)!r}"
