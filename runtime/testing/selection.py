"""``mint test -k``: which tests a keyword expression selects, as pytest's ``-k`` selects them.

A name in the expression holds for a test whose path, as the report shows it, contains it without regard to case;
``not`` binds tighter than ``and``, ``and`` than ``or``, and brackets group (the keywords in lower case, as
pytest's: ``AND`` is a name). lark, a dependency, parses it; importing it is left to a run given ``-k``.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import cache

import lark

Selector = Callable[[str], bool]
"""Whether the test of this path is selected."""

_GRAMMAR = r"""
start: either
?either: both ("or" both)*
?both: negated ("and" negated)*
?negated: "not" negated -> negation
        | "(" either ")"
        | NAME
NAME: /[\w:+\-.\[\]\\\/]+/
%ignore /[ \t]+/
"""
# NAME is pytest's identifier: a path's separators, dots and a parameter's brackets read as part of a name

_WORDS = {"NAME": "a name", "NOT": "'not'", "AND": "'and'", "OR": "'or'", "LPAR": "'('", "RPAR": "')'"}
_OTHER_LANGUAGES = {"&": "and", "|": "or", "!": "not", "~": "not"}


class KeywordError(ValueError):
    """An expression that cannot be read: the message says where (its column, from 1) and what would do."""


def selector(expression: str) -> Selector:
    """The tests ``expression`` selects; a blank one selects every test, as pytest's empty ``-k`` does."""
    if not expression.strip():
        return lambda _path: True
    try:
        return _Predicate().transform(_parser().parse(expression))
    except lark.exceptions.UnexpectedCharacters as error:
        raise KeywordError(_unexpected_character(expression, error.column)) from None
    except lark.exceptions.UnexpectedToken as error:
        raise KeywordError(_unexpected_token(expression, error)) from None


@cache
def _parser() -> lark.Lark:
    return lark.Lark(_GRAMMAR, parser="lalr", lexer="basic")


class _Predicate(lark.Transformer[lark.Token, Selector]):
    """Each part of the parsed expression as the test it puts to a path."""

    def NAME(self, token: lark.Token) -> Selector:  # lark calls a terminal's method by the terminal's name
        word = token.lower()
        return lambda path: word in path.lower()

    def start(self, children: list[Selector]) -> Selector:
        return children[0]

    def negation(self, children: list[Selector]) -> Selector:
        inner = children[0]
        return lambda path: not inner(path)

    def both(self, children: list[Selector]) -> Selector:
        return lambda path: all(part(path) for part in children)

    def either(self, children: list[Selector]) -> Selector:
        return lambda path: any(part(path) for part in children)


def _unexpected_character(expression: str, column: int) -> str:
    character = expression[column - 1]
    instead = _OTHER_LANGUAGES.get(character)
    if instead is not None:
        return f"at column {column}: '{character}' is written '{instead}'"
    return f"at column {column}: a name is letters, digits and _ : + - . [ ] \\ /, not '{character}'"


def _unexpected_token(expression: str, error: lark.exceptions.UnexpectedToken) -> str:
    """What was wanted where the expression went wrong, ``)`` only inside a bracket (LALR offers it at the top
    level too, its states shared by both)."""
    at_end = error.token.type == "$END"
    column = len(expression) + 1 if at_end else error.column
    opened = expression[: column - 1].count("(") - expression[: column - 1].count(")")
    wanted = [word for name, word in _WORDS.items() if name in error.expected and (name != "RPAR" or opened > 0)]
    if not wanted:
        return f"at column {column}: ')' closes no '('"
    listed = wanted[0] if len(wanted) == 1 else f"{', '.join(wanted[:-1])} or {wanted[-1]}"
    if at_end:
        return f"at column {column}: the expression ends where {listed} should follow"
    return f"at column {column}: expected {listed}, not '{error.token}'"
