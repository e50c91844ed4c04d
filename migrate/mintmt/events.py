"""v4's ``#COMMS1`` … ``RETURN`` handlers become MintMT's ``Event Comms1`` … ``End Event`` (002:79-85).

The comms note shows the correspondence for the comms locations 1 to 5 that raise
an event (002:19, MT-13). A handler is rewritten only when the block says the
same thing: its label alone on its line (``#COMMS01`` is a plain label, see
``mintlang.semantic.events``), one ``RETURN`` alone on its line ending it (a ``:`` before a
comment is no statement, ``Line.statement_kinds``), no other
label, ``RETURN`` or ``GOTO`` between (a ``GOTO`` leaves the handler, whose
``RETURN`` is then the label's it went to), no jump naming it, and code above it
that cannot run into it (v4 would run into the handler, a MintMT ``Event`` is stepped
over, MT-7). Any other handler is kept and flagged, as are the other event handlers
(``#IN0``, ``#ONERROR``, ``#TIMER`` …: the notes show no MintMT form of them) and
every other label (the notes show no MintMT subroutine): MintMT reads them as v4
does (MT-1).
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.migrate.mintmt.source import Action, Flag, Line, Rewrite, Source, span, styled
from mintlang.semantic.events import EventKind, event_of
from mintlang.syntax.tokens import TokenKind

ID = "MT-EVENT"
SUMMARY = "#COMMS1..#COMMS5 handlers become Event Comms1..5 blocks; other labels are flagged"

_K = TokenKind
_COMMS_EVENTS = range(1, 6)
_EVENTS_SHOWN = "the notes show MintMT Event blocks only for MOVEBUFFERLOW and Comms1..Comms5"
_STOPS = ((_K.END,), (_K.RETURN,))  # a line alone that the code above a handler may end with
_OPENERS = (_K.LOOP, _K.FOR, _K.WHILE, _K.REPEAT)  # with a block IF, what a closer below ends
_CLOSERS = (_K.ENDL, _K.NEXT, _K.ENDW, _K.UNTIL, _K.ENDIF)


def find(source: Source) -> Iterator[Action]:
    lines = source.lines
    for position, line in enumerate(lines):
        if not line.tokens or line.kinds[0] is not _K.LABEL:
            continue
        label = line.tokens[0]
        event = event_of(label.text[1:])
        if event is None:
            yield Flag(ID, label.start, f"{label.text} is kept as v4 writes it: the notes show no MintMT subroutine")
        elif event.kind is not EventKind.COMMS or event.number not in _COMMS_EVENTS:
            yield Flag(ID, label.start, f"the handler {label.text} is kept as v4 writes it: {_EVENTS_SHOWN}")
        else:
            yield from _comms_handler(source, position, event.number)


def _comms_handler(source: Source, position: int, number: int) -> Iterator[Action]:
    lines = source.lines
    label = lines[position].tokens[0]
    end = _return_line(lines, position)
    why = _why_not(source, position, end)
    if why is not None or end is None:
        yield Flag(ID, label.start, f"{label.text} is kept as a v4 handler: {why}")
        return
    yield Rewrite(ID, span(label), styled(f"Event Comms{number}", label.text))
    returning = lines[end].tokens[0]
    yield Rewrite(ID, span(returning), styled("End Event", returning.text))


def _return_line(lines: tuple[Line, ...], label: int) -> int | None:
    """The line of the handler's ``RETURN`` alone, when it is the handler's only ``RETURN`` and no
    label comes before it. A ``RETURN`` inside one of the handler's blocks returns early: ``End Event``
    there would close the event inside its ``If``."""
    depth = 0
    for position in range(label + 1, len(lines)):
        kinds = lines[position].kinds
        if lines[position].statement_kinds == (_K.RETURN,) and depth == 0:
            return position
        if _K.RETURN in kinds or (kinds and kinds[0] is _K.LABEL):
            return None
        depth += sum(kinds.count(kind) for kind in _OPENERS) - sum(kinds.count(kind) for kind in _CLOSERS)
        depth += _K.IF in kinds and _K.DO in kinds  # a block IF
    return None


def _why_not(source: Source, label: int, end: int | None) -> str | None:
    """Why the comms handler at line index ``label`` cannot be an ``Event`` block, or None."""
    line = source.lines[label]
    name = line.tokens[0].text[1:].upper()
    if len(line.statement_kinds) > 1:
        return "a statement follows its label on the line"
    if end is None:
        return "it does not end with one RETURN alone on its line before the next label"
    if any(_K.GOTO in source.lines[position].kinds for position in range(label + 1, end)):
        return "a GOTO leaves it for a label whose RETURN ends it in v4; an Event block ends only at End Event"
    if name in _jump_targets(source):
        return "the program names it in a GOSUB or GOTO"
    if _runs_into(source.lines, label):
        return "the code above it can run into it (v4 runs the handler's lines, MintMT steps over an Event block)"
    return None


def _jump_targets(source: Source) -> set[str]:
    """The upper-case label names the file's ``GOSUB`` and ``GOTO`` statements name."""
    return {
        line.tokens[index + 1].text.upper()
        for line, index, token in source.tokens()
        if token.kind in {_K.GOSUB, _K.GOTO} and index + 1 < len(line.tokens)
    }


def _runs_into(lines: tuple[Line, ...], label: int) -> bool:
    """Whether the code above line index ``label`` can go on into it: it does not end with ``END``,
    ``RETURN``, ``GOTO`` or a ``LOOP`` with no ``EXIT``."""
    above = next((position for position in range(label - 1, -1, -1) if lines[position].statement_kinds), None)
    if above is None:
        return True  # the program starts with it
    kinds = lines[above].statement_kinds
    if kinds in _STOPS or (kinds[0] is _K.GOTO and len(kinds) == 2):
        return False
    return not (kinds == (_K.ENDL,) and _endless(lines, above))


def _endless(lines: tuple[Line, ...], closing: int) -> bool:
    """Whether the ``LOOP`` the ``ENDL`` at line index ``closing`` closes holds no ``EXIT`` or ``GOTO``
    that could leave it."""
    depth = 0
    for position in range(closing, -1, -1):
        kinds = lines[position].kinds
        if _K.EXIT in kinds or _K.GOTO in kinds:
            return False
        depth += kinds.count(_K.ENDL) - kinds.count(_K.LOOP)
        if depth == 0:
            return True
    return False
