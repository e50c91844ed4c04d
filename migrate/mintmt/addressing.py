"""A keyword's axes or channel in round brackets: ``MOVER.0`` and ``MOVER[0]`` become ``MOVER(0)`` (004).

The notes write one axis or channel ``MOVER(0)``, ``POS(0)``, ``OUTX(0)``, several
``GO(0,1)`` and ``VECTORA(0,1) = 10, 10``, and axes that all take one value (v4's
``;``) ``MOVEBUFFERSIZE([0,1]) = 4;``; the project reads each the way v4 reads
``[0]``, ``.0`` and ``[0,1]`` (mintlang/MINTMT.md). So the bracket or dot is
replaced and what is inside copied as written (MT-18). v4's ``OUT.2``, one output
channel, is ``OUTX(2)``: the note's "turn on digital output 0" (004:148).

Kept as v4 writes it, which MintMT reads too (MT-4): ``.(a+1)`` (round brackets,
like v4's square ones, take a number or a variable), a dot form with several
values (``REMOTEIN.2.65``), the forms a macro gives (``SPEED.AX``, ``SPEED.[0,1]``)
and a function's dot (``COMMS`` is a function: its ``(`` is an argument list).
Flagged: ``AXES``, whose MintMT form the notes do not show. (A keyword followed
by ``(``, which MintMT reads as its axes, makes the text MintMT already: ``api``
leaves it as it is.)
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.diagnostics import Span
from mintlang.dialect import Dialect
from mintlang.migrate.mintmt.source import Action, Flag, Line, Rewrite, Source, span, styled, touches
from mintlang.syntax.tokens import Token, TokenKind
from mintlang.syntax.vocabulary import vocabulary

ID = "MT-ADDRESS"
SUMMARY = "a keyword's .axis and [axes] become (axis) and (axes), or ([axes]) before a ;, OUT.n OUTX(n)"

_K = TokenKind
_DOT_VALUES = frozenset({_K.NUMBER, _K.NAME, _K.CONSTANT})


def find(source: Source) -> Iterator[Action]:
    for line, index, token in source.tokens():
        if token.kind is _K.AXES:
            yield Flag(ID, token.start, "AXES is kept as v4 writes it: the notes show no MintMT form of it")
        if token.kind is not _K.KEYWORD:
            continue
        after = source.following(line, index)
        if after is None:
            continue
        if after.kind is _K.DOT and touches(token, after):
            selector = list(_dot(source, line, index + 1))
        elif after.kind is _K.LSQB:
            selector = list(_square(line, index + 1))
        else:
            continue
        yield from selector
        if selector and _one_output(token, selector[0]):
            yield Rewrite(ID, span(token), styled("OUTX", token.text))


def _one_output(keyword: Token, selector: Rewrite) -> bool:
    """Whether ``keyword`` is v4's ``OUT`` addressing one channel (``OUT.2``): MintMT's ``OUTX(2)`` (004:148)."""
    one = "," not in selector.text  # a channel is a number or a variable: no inner comma
    return one and vocabulary(Dialect.V4).canonical.get(keyword.text.upper()) == "OUT"


def _dot(source: Source, line: Line, dot: int) -> Iterator[Action]:
    """``KW.value``, one value only: ``KW(value)``."""
    tokens = line.tokens
    value = tokens[dot + 1] if dot + 1 < len(tokens) else None
    if value is None or value.kind not in _DOT_VALUES or _another_dot(tokens, dot + 1):
        return  # KW.(a+1) too: round brackets take a number or a variable (the v4 rule), so the dot stays
    if value.kind is _K.NAME and value.text.upper() in source.macros:
        return  # what the macro stands for decides the form: left as v4 writes it (MT-4)
    yield Rewrite(ID, Span(tokens[dot].start, value.end), f"({value.text})")


def _another_dot(tokens: tuple[Token, ...], index: int) -> bool:
    return index + 1 < len(tokens) and tokens[index + 1].kind is _K.DOT and touches(tokens[index], tokens[index + 1])


def _square(line: Line, opening: int) -> Iterator[Action]:
    """``KW[axes]``: ``KW(axes)``, or ``KW([axes])`` for several axes given one value by ``;``."""
    tokens = line.tokens
    close = _closing(tokens, opening, _K.LSQB, _K.RSQB)
    if close is None:
        return
    written = line.lexed.text[tokens[opening].start - line.offset : tokens[close].end - line.offset]
    several = any(token.kind is _K.COMMA for token in _top_level(tokens, opening, close))
    replacement = f"({written})" if several and _ends_with_fill(tokens, close) else f"({written[1:-1]})"
    yield Rewrite(ID, Span(tokens[opening].start, tokens[close].end), replacement)


def _closing(tokens: tuple[Token, ...], opening: int, opens: TokenKind, closes: TokenKind) -> int | None:
    """The index of the bracket that closes ``tokens[opening]`` on its line, if it has one."""
    depth = 0
    for index in range(opening, len(tokens)):
        kind = tokens[index].kind
        depth += (kind is opens) - (kind is closes)
        if depth == 0:
            return index
    return None


def _top_level(tokens: tuple[Token, ...], opening: int, close: int) -> Iterator[Token]:
    """The tokens between two brackets that no inner bracket holds."""
    depth = 0
    for token in tokens[opening + 1 : close]:
        if token.kind in {_K.LPAR, _K.LSQB}:
            depth += 1
        elif token.kind in {_K.RPAR, _K.RSQB}:
            depth -= 1
        elif depth == 0:
            yield token


def _ends_with_fill(tokens: tuple[Token, ...], after: int) -> bool:
    """Whether the statement holding ``tokens[after]`` ends with ``;`` (one value for every axis)."""
    last = None
    for token in tokens[after + 1 :]:
        if token.kind is _K.COLON:
            break
        last = token
    return last is not None and last.kind is _K.SEMICOLON
