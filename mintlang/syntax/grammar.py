"""lark's LALR parser over one logical line, with a cache by token kinds.

An LR parse depends only on the sequence of terminal kinds, never on token
texts, so the tree shape computed for ``KEYWORD EQUAL NUMBER`` serves every
``SPEED = 10`` and ``ACCEL = 2000`` of a program; the cache keeps it compiled
into a builder (``build.py``). Leaves of cached trees hold
the position of their token in the line (``Token.start_pos``), and subtrees
the positions of their first and last token (``Tree.meta``); the builder reads
texts and spans from the line itself.

The parser is lark's stand-alone one (``lark_runtime.py``) over the tables the
package ships: neither imports lark itself (``tables.py`` says why and makes them).
"""

from __future__ import annotations

import marshal
from collections.abc import Iterator
from functools import cache
from typing import Any

from mintlang.dialect import Dialect
from mintlang.package_data import read_bytes
from mintlang.records import record
from mintlang.syntax.build import LineBuilder, compile_line
from mintlang.syntax.grammars import grammar_of, grammar_text
from mintlang.syntax.lark_runtime import (
    Lark,
    Lexer,
    LexerConf,
    NonTerminal,
    Reduce,
    Rule,
    RuleOptions,
    Shift,
    Symbol,
    Terminal,
    Token,
    Tree,
    UnexpectedInput,
    UnexpectedToken,
)
from mintlang.syntax.lexer import MAX_TOKENS
from mintlang.syntax.tokens import TokenKind


class _PresetTokens(Lexer):
    """Hands lark the tokens our own lexer made (lark's regex lexer cannot lex Mint)."""

    def __init__(self, lexer_conf: LexerConf) -> None:  # lark's Lexer interface
        del lexer_conf

    def lex(self, data: list[Token]) -> Iterator[Token]:  # type: ignore[override]
        return iter(data)


def shipped_tables(dialect: Dialect) -> dict[str, Any]:
    """What ``tools/lalr_tables.py`` wrote for ``dialect``: the ``grammar`` text the tables were computed
    from, the ``lark`` version that computed them, and lark's serialization of the ``parser``."""
    return marshal.loads(read_bytes("mintlang.syntax", f"lalr_{grammar_of(dialect).value}.bin"))


class _StatesDecodedOnUse(dict[int, dict[str, tuple[Any, Any]]]):
    """The parse table's states (state -> terminal or rule name -> action), each read from its marshalled
    serialization (``tables.computed``) the first time the parser looks it up: the lines of a small
    program visit a few dozen of the 359 states, and reading all of them was a third of loading the parser.

    The runtime's parser only looks states up; what would iterate the table (``Lark.save``, lark's
    contextual lexer) is never used here.
    """

    def __init__(self, encoded: dict[int, bytes], names: dict[int, str], rules: dict[int, Rule]) -> None:
        super().__init__()
        self._encoded, self._names, self._rules = encoded, names, rules

    def __missing__(self, state: int) -> dict[str, tuple[Any, Any]]:
        # As lark's ParseTableBase.deserialize: action 1 reduces by a rule (a reference into the memo), 0 shifts.
        decoded = {
            self._names[name]: (Reduce, self._rules[argument["@"]]) if action == 1 else (Shift, argument)
            for name, (action, argument) in marshal.loads(self._encoded[state]).items()
        }
        self[state] = decoded
        return decoded


def _symbol(data: dict[str, Any]) -> Symbol:
    kind = data["__type__"]
    if kind == "Terminal":
        return Terminal(data["name"], data["filter_out"])
    if kind == "NonTerminal":
        return NonTerminal(data["name"])
    raise KeyError(kind)  # as for any other shape: ``_parser`` then has lark build the parser


def decoded_rules(memo: dict[int, dict[str, Any]]) -> dict[int, Rule]:
    """The grammar's rules (all that lark's serialization keeps by reference), built by their constructors.

    lark's generic deserialization walks every dict of them, looks each ``__type__`` up in a namespace it
    builds per object and sets each field with ``setattr``: 22.5 of the 30.6 million instructions of
    loading a parser, against 6.4 this way. The result is what lark makes of the same data
    (``tests/core/test_parser_rules_decoded.py``)."""
    rules = {}
    for reference, rule in memo.items():
        if rule["__type__"] != "Rule":
            raise KeyError(rule["__type__"])
        options = rule["options"]
        rules[reference] = Rule(
            _symbol(rule["origin"]),
            [_symbol(symbol) for symbol in rule["expansion"]],
            rule["order"],
            rule["alias"],
            RuleOptions(
                options["keep_all_tokens"],
                options["expand1"],
                options["priority"],
                options["template_source"],
                options["empty_indices"],
            ),
        )
    return rules


def load_parser(serialized: dict[str, Any]) -> Lark:
    """The runtime's parser over lark's serialization of one, reading the tokens our lexer made; its
    parse table's states are decoded when first used (``_StatesDecodedOnUse``)."""
    data = serialized["data"]
    # Without lark's propagation of positions: it wrapped every reduction in isinstance and getattr
    # calls, three quarters of a parse; ``_place`` gives the cached tree the same positions once.
    options = {**data["options"], "lexer": _PresetTokens, "propagate_positions": False}
    table = data["parser"]["parser"]
    parser = {
        **data["parser"],
        "lexer_conf": {**data["parser"]["lexer_conf"], "lexer_type": _PresetTokens},
        "parser": {**table, "states": {}},
    }
    # lark's loader passes objects already built through as they are (``decoded_rules``).
    memo = decoded_rules(serialized["memo"])
    loaded = Lark.load({"data": {**data, "options": options, "parser": parser}, "memo": memo})
    rules = {reference["@"]: rule for reference, rule in zip(data["rules"], loaded.rules, strict=True)}
    # lark's LALR parser and the ParseConf of each parse read the states from this one table object.
    loaded.parser.parser._parse_table.states = _StatesDecodedOnUse(table["states"], table["tokens"], rules)
    return loaded


@cache
def _parser(dialect: Dialect) -> Lark:
    """The shipped parser when it was made from this grammar, else one made now with lark itself
    (after an edit of grammar.lark, until ``python -m tools.lalr_tables`` is run)."""
    try:
        shipped = shipped_tables(dialect)
        if shipped["grammar"] == grammar_text(dialect):
            return load_parser(shipped["parser"])
    except (OSError, KeyError, ValueError, EOFError, TypeError):
        pass  # missing or unreadable: compute them
    from mintlang.syntax.tables import computed  # noqa: PLC0415 - lark's grammar compiler, only then

    return load_parser(computed(dialect))


# Beyond these the line is not analysed: the controller takes 255 characters a line,
# and the tree builder and the rules recurse once per level of nesting. The lexer
# stops at MAX_TOKENS and makes the rest of the line one more token.
MAX_DEPTH = 200


@record
class ParseFailure:
    """Where the grammar stopped: the index of the offending token (len = end of line).

    ``too_complex`` is set instead when the line is too long or too deeply
    nested to analyse.
    """

    index: int
    expected: frozenset[str]
    too_complex: str | None = None


ParseResult = LineBuilder | ParseFailure

_results: dict[tuple[Dialect, tuple[TokenKind, ...]], ParseResult] = {}
_CACHE_LIMIT = 200_000


def clear_cache() -> None:
    _results.clear()


def parse_kinds(kinds: tuple[TokenKind, ...], dialect: Dialect = Dialect.V4) -> ParseResult:
    """The builder for lines with these token kinds, or where the grammar rejects them."""
    grammar = grammar_of(dialect)
    key = (grammar, kinds)
    result = _results.get(key)
    if result is None:
        result = _parse(kinds, grammar)
        if len(_results) >= _CACHE_LIMIT:
            _results.clear()
        _results[key] = result
    return result


def _parse(kinds: tuple[TokenKind, ...], dialect: Dialect) -> ParseResult:
    if len(kinds) > MAX_TOKENS:
        return ParseFailure(0, frozenset(), f"more than {MAX_TOKENS} tokens on one line")
    stream = [Token(kind.value, kind.value, start_pos=index, end_pos=index) for index, kind in enumerate(kinds)]
    try:
        tree = _parser(dialect).parse(stream)  # type: ignore[arg-type]
    except UnexpectedToken as error:
        index = error.token.start_pos if error.token.type != "$END" else len(kinds)
        return ParseFailure(index if index is not None else len(kinds), frozenset(error.expected))
    except UnexpectedInput:
        return ParseFailure(len(kinds), frozenset())
    depth = _depth(tree)
    if depth > MAX_DEPTH:
        return ParseFailure(0, frozenset(), f"expressions nested {depth} deep")
    for subtree in tree.iter_subtrees():  # children before their parents
        subtree.data = str(subtree.data)  # lark names rules with Tokens, slow to hash
        _place(subtree)
    return compile_line(tree)


def _place(tree: Tree) -> None:
    """Give ``tree`` the indices of its first and last token in its ``meta``, as lark's
    ``propagate_positions`` did: its subtrees have theirs already; one without a token gets none."""
    children = tree.children
    first = next((found for found in (_position(child, "start_pos") for child in children) if found is not None), None)
    if first is not None:
        ends = (_position(child, "end_pos") for child in reversed(children))
        meta = tree.meta
        meta.start_pos, meta.end_pos, meta.empty = first, next(found for found in ends if found is not None), False


def _position(child: Tree | Token | None, which: str) -> int | None:
    """``which`` position of a token, or of a subtree that holds one."""
    if isinstance(child, Tree):
        return None if child.meta.empty else getattr(child.meta, which)
    return getattr(child, which) if isinstance(child, Token) else None


def _depth(tree: Tree) -> int:
    """Height of a tree, measured without recursion."""
    deepest = 0
    stack = [(tree, 1)]
    while stack:
        node, depth = stack.pop()
        deepest = max(deepest, depth)
        stack.extend((child, depth + 1) for child in node.children if isinstance(child, Tree))
    return deepest
