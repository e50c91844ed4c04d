"""Block words as the notes write them: ``LOOP … ENDL`` ends ``End Loop``, ``IF … DO … ENDIF`` becomes
``If … Then … End If`` (004:96-105, 002:48-73).

MintMT's ``Then`` opens a block only when it ends its line (the lexer reads it as
v4's ``DO`` there; a comment after it is no statement), so a ``DO`` followed by a
``:`` and a comment loses the ``:``, and one with a statement after it on its line
is kept and flagged. ``WHILE … ENDW`` and ``REPEAT … UNTIL`` are kept as v4 writes them, which
MintMT reads (MT-1), and flagged: the notes show no MintMT form of them.
The new words take the case of the words they replace (MT-21).
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence

from mintlang.diagnostics import Span
from mintlang.migrate.mintmt.source import Action, Flag, Line, Rewrite, Source, span, styled
from mintlang.syntax.tokens import Token, TokenKind

ID = "MT-BLOCK"
SUMMARY = "ENDL becomes End Loop, a block IF's DO and ENDIF become Then and End If"

_K = TokenKind
_CLOSERS = {_K.ENDL: "End Loop", _K.ENDIF: "End If"}
_UNSHOWN = {
    _K.WHILE: "WHILE ... ENDW is kept as v4 writes it: the notes show no MintMT form of it",
    _K.REPEAT: "REPEAT ... UNTIL is kept as v4 writes it: the notes show no MintMT form of it",
}


def find(source: Source) -> Iterator[Action]:
    closed = _closed_blocks(source)
    for line, index, token in source.tokens():
        kind = token.kind
        if kind in _CLOSERS:
            yield Rewrite(ID, span(token), styled(_CLOSERS[kind], token.text))
        elif kind is _K.DO and _K.IF in line.kinds:
            separators = line.tokens[index + 1 :]
            if all(separator.kind is _K.COLON for separator in separators):
                if token.start in closed:
                    yield Rewrite(ID, span(token), styled("Then", token.text))
                    if separators:  # only a comment follows: ``DO : REM c`` is ``Then ' c``
                        yield _without_separators(source, line, separators)
            else:
                reason = "DO is kept: MintMT's Then opens a block only at the end of its line; move what follows it"
                yield Flag(ID, token.start, reason)
        elif kind is _K.THEN and index == len(line.tokens) - 1 and _K.IF in line.kinds:
            reason = "THEN ends its line: MintMT reads it as opening an If block; give it its statement"
            yield Flag(ID, token.start, reason)
        elif kind in _UNSHOWN:
            yield Flag(ID, token.start, _UNSHOWN[kind])


def _without_separators(source: Source, line: Line, separators: Sequence[Token]) -> Rewrite:
    """The ``:`` between a block's ``DO`` and a comment removed, with the spaces up to the comment; a
    space stays between the two where the ``:`` touched the ``DO`` (``do: rem c`` is ``then ' c``)."""
    start = separators[0].start
    end = line.comment.start if line.comment is not None else separators[-1].end
    return Rewrite(ID, Span(start, end), "" if source.text[start - 1] in " \t" else " ")


def _closed_blocks(source: Source) -> frozenset[int]:
    """Where the ``DO`` of each ``IF`` block that an ``ENDIF`` closes is. An ``IF … DO`` never closed
    is left as it is: as ``IF … Then`` it would read back as a v4 ``IF … THEN`` with no statement."""
    open_blocks: list[int] = []
    closed: set[int] = set()
    for line, _, token in source.tokens():
        if token.kind is _K.DO and _K.IF in line.kinds:
            open_blocks.append(token.start)
        elif token.kind is _K.ENDIF and open_blocks:
            closed.add(open_blocks.pop())
    return frozenset(closed)
