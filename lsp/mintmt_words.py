"""MintMT's block words as MintMT writes them (``Loop … End Loop``, ``Event Comms1 … End Event``), for hover
and completion: the keyword database describes v4's spellings (``LOOP … ENDL``), which MintMT writes otherwise.

Facts from the move buffer note (004: the Startup block, the main Loop, Event MOVEBUFFERLOW) and the comms
note (002: Event Comms1 to Comms5), as ``mintlang/MINTMT.md`` reads them.
"""

from __future__ import annotations

from mintlang.dialect import Dialect
from mintlang.lsp.lookup import significant
from mintlang.records import record
from mintlang.semantic.events import EventKind, event_of
from mintlang.syntax.parser import Document
from mintlang.syntax.tokens import Token, TokenKind


@record
class BlockWord:
    """One of MintMT's block words: its spelling, the block it belongs to, and what it does."""

    spelling: str
    block: str  # the whole block as MintMT writes it, shown in a code fence
    summary: str


_LOOP = "Loop\n  {statements}\nEnd Loop"
_IF = "If <condition> Then\n  {statements}\nEnd If"
_EVENT = "Event NAME\n  {statements}\nEnd Event"
_STARTUP = "Startup\n  {statements}\nEnd Startup"

WORDS: dict[TokenKind, BlockWord] = {
    TokenKind.LOOP: BlockWord(
        "Loop", _LOOP, "Runs its statements again and again, until an EXIT leaves it (v4's LOOP … ENDL)."
    ),
    TokenKind.ENDL: BlockWord("End Loop", _LOOP, "Closes a Loop block: the program goes back to its Loop."),
    TokenKind.IF: BlockWord(
        "If",
        _IF,
        "Runs what follows Then when the condition is true: the rest of the line, or, when Then ends its"
        " line, the block up to End If (v4's IF … THEN and IF … DO … ENDIF).",
    ),
    TokenKind.ENDIF: BlockWord(
        "End If",
        _IF,
        "Closes an If block, opened by an If whose Then ends its line (v4's IF … DO … ENDIF); EndIf is the same.",
    ),
    TokenKind.EVENT: BlockWord(
        "Event",
        _EVENT,
        "The block the controller runs when the event NAME happens: Comms1 to Comms5 when a host writes that"
        " comms location, MOVEBUFFERLOW when the move buffer's free places reach their level, or one of v4's"
        " events (ONERROR, TIMER, STOP, INx, FASTINx, CANx). The program"
        " never runs into it from the line above.",
    ),
    TokenKind.ENDEVENT: BlockWord(
        "End Event", _EVENT, "Closes an Event block: the controller goes back to what the event interrupted."
    ),
    TokenKind.STARTUP: BlockWord(
        "Startup",
        _STARTUP,
        "Code the controller runs when it powers up: the place to size the move"
        " buffer (MOVEBUFFERSIZE) before any axis is enabled.",
    ),
    TokenKind.ENDSTARTUP: BlockWord("End Startup", _STARTUP, "Closes the Startup block."),
}

_THEN = BlockWord("Then", _IF, "Ending its line, opens an If block that End If closes (v4's DO).")

SNIPPETS = {
    "Loop … End Loop": "Loop\n\t$0\nEnd Loop",
    "If … Then … End If": "If ${1:condition} Then\n\t$0\nEnd If",
    "Event … End Event": "Event ${1:Comms1}\n\t$0\nEnd Event",
    "Startup … End Startup": "Startup\n\t$0\nEnd Startup",
}

TOP_LEVEL_SNIPPETS = frozenset({"Event … End Event", "Startup … End Startup"})  # in no other block (MT-13)

REPLACED = frozenset({"ENDL", "ENDIF"})  # v4's closers MintMT writes as End Loop and End If
COMPLETED = (
    TokenKind.ENDL,
    TokenKind.ENDIF,
    TokenKind.EVENT,
    TokenKind.ENDEVENT,
    TokenKind.STARTUP,
    TokenKind.ENDSTARTUP,
)


def describe(word: BlockWord) -> str:
    return f"**{word.spelling}** — MintMT block\n\n```mint\n{word.block}\n```\n\n{word.summary}"


# The events an Event block can name (MT-13): a host's write to comms locations 1 to 5 (002:19) and the move
# buffer running low (004:114), spelt as the notes spell them; v4's handlers' events besides (``event_name``).
EVENT_BLOCK_NAMES = (*(f"Comms{location}" for location in range(1, 6)), "MOVEBUFFERLOW")

# What calls the block of each of v4's events, a number standing for the input or channel (000:1889-1898, chapter 8).
_V4_EVENTS = {
    EventKind.ONERROR: "an error happens (v4's #ONERROR)",
    EventKind.TIMER: "the periodic timer ticks, at the interval TIMEREVENT sets",
    EventKind.STOP: "an axis's stop input becomes active",
    EventKind.IN: "digital input {number} raises its event",
    EventKind.FASTIN: "fast position latch input {number} latches",
    EventKind.CAN: "CAN channel {number} raises an event",
}


def event_name(name: str) -> str | None:
    """What the event an ``Event`` block names is, for the events MintMT raises (MT-13); None otherwise."""
    event = event_of(name, Dialect.MINTMT)
    if event is None:
        return None
    if event.kind is EventKind.COMMS and event.number is not None and 1 <= event.number <= 5:
        when = f"a host writes comms location {event.number} (COMMS({event.number}))"
    elif event.kind is EventKind.MOVEBUFFERLOW:
        when = "the free places of an axis's move buffer come up to the level MOVEBUFFERLOW sets"
    elif event.kind is EventKind.FASTIN and event.number is None:
        when = "a fast position latch input latches"
    elif event.kind in _V4_EVENTS:
        when = _V4_EVENTS[event.kind].format(number=event.number)
    else:
        return None
    return f"**{name}** — MintMT event: the controller runs this Event block when {when}"


def hover(document: Document, token: Token) -> str | None:
    """The hover of ``token`` if it is a MintMT block word or the name an ``Event`` block handles."""
    word = _THEN if token.kind is TokenKind.DO and token.text.upper() == "THEN" else WORDS.get(token.kind)
    if word is not None:
        return describe(word)
    return event_name(token.text) if names_an_event_block(document, token) else None


def names_an_event_block(document: Document, token: Token) -> bool:
    """Whether ``token`` is the name an ``Event`` block handles, the word after ``Event``."""
    before = significant([found for found in document.tokens_in(token.start, token.start) if found.end <= token.start])
    return bool(before) and before[-1].kind is TokenKind.EVENT
