"""Matching block openers with their closers, as the controller's compiler does.

The grammar leaves IF..DO/ELSE/ENDIF, FOR/NEXT, REPEAT/UNTIL, WHILE/ENDW and
LOOP/ENDL as separate statements; a stack matches them here. A closer whose
opener is not on top of the stack is the controller's error 2009 (NEXT),
2011 (ELSE/ENDIF), 2012 (ENDW), 2013 (UNTIL) or 2014 (ENDL); it is then
ignored, so one misplaced closer gives one error. A block still open at the
end of the file is the same mismatch seen from the other side, and the
compiler traps it too (section 8.4, "a mismatch loop construct will be
trapped"); the manual numbers only the closers, so it gets its construct's
number: a FOR without NEXT is 2009, an IF .. DO without ENDIF 2011. An ELSE
or ENDIF without IF .. DO that follows an ``IF .. THEN`` with nothing after
its THEN is offered the fix of writing DO: that IF was meant as the block.
The nesting limits of section 3.9 give error 2015.

MintMT adds ``Event NAME .. End Event`` and ``Startup .. End Startup`` (its
``End Loop`` and ``End If`` lex as ENDL and ENDIF). The notes give no error
numbers for them: a mismatch is reported as the syntax error 2003
(mintlang/MINTMT.md).
"""

from __future__ import annotations

from collections.abc import Hashable, Iterable, Mapping
from enum import StrEnum
from typing import NamedTuple

from mintlang.analysis.suggestions import OTHER_BASICS, closest, did_you_mean
from mintlang.codes import mint_error
from mintlang.controllers import ControllerProfile, NestingLimits, nesting_of
from mintlang.diagnostics import Diagnostic, Edit, Fix, Span
from mintlang.dialect import Dialect
from mintlang.records import record
from mintlang.semantic.events import Event, EventKind, event_of
from mintlang.semantic.index import LineFacts
from mintlang.syntax import nodes as n
from mintlang.syntax.tokens import in_a_word


class BlockKind(StrEnum):
    IF = "IF"
    FOR = "FOR"
    REPEAT = "REPEAT"
    WHILE = "WHILE"
    LOOP = "LOOP"
    EVENT = "Event"  # MintMT
    STARTUP = "Startup"  # MintMT


_CLOSERS: dict[str, tuple[BlockKind, int, str, str]] = {  # the kind, the mismatch's number, the words to name
    "ENDIF": (BlockKind.IF, 2011, "ENDIF", "IF .. DO"),
    "NEXT": (BlockKind.FOR, 2009, "NEXT", "FOR"),
    "ENDW": (BlockKind.WHILE, 2012, "ENDW", "WHILE"),
    "ENDL": (BlockKind.LOOP, 2014, "ENDL", "LOOP"),
    "ENDEVENT": (BlockKind.EVENT, 2003, "End Event", "Event"),
    "ENDSTARTUP": (BlockKind.STARTUP, 2003, "End Startup", "Startup"),
}
# How MintMT writes the words of the blocks it spells otherwise (its notes: If .. Then .. End If, Loop .. End Loop).
_MINTMT_WORDS = {"ENDIF": "End If", "IF .. DO": "If .. Then", "ENDL": "End Loop", "LOOP": "Loop", "IF": "If"}
_CLOSING = {  # the word that closes each kind of block, and the number of the construct's mismatch
    BlockKind.IF: ("ENDIF", 2011),
    BlockKind.FOR: ("NEXT", 2009),
    BlockKind.REPEAT: ("UNTIL", 2013),
    BlockKind.WHILE: ("ENDW", 2012),
    BlockKind.LOOP: ("ENDL", 2014),
    BlockKind.EVENT: ("End Event", 2003),
    BlockKind.STARTUP: ("End Startup", 2003),
}
LOOPS = frozenset({BlockKind.FOR, BlockKind.REPEAT, BlockKind.WHILE, BlockKind.LOOP})
_TOP_LEVEL = frozenset({BlockKind.EVENT, BlockKind.STARTUP})  # MintMT: never inside another block
_COMMS_EVENTS = range(1, 6)  # the comms locations whose update raises an event (002:19, 77-79)
_NAMED_EVENTS = ("MOVEBUFFERLOW", "ONERROR", "TIMER", "STOP", *(f"COMMS{number}" for number in _COMMS_EVENTS))
BLOCK_STATEMENTS = frozenset(
    {n.BlockWord, n.IfDo, n.IfThen, n.For, n.While, n.Until, n.SyntaxError_, n.EventBlock, n.BareName}
)


class _BareThen(NamedTuple):
    """An IF .. THEN with nothing after THEN, at ``depth`` blocks deep: the stray ELSE and ENDIF after it
    are offered ``fix``, DO for its THEN, until the block DO would open has taken its ELSE and ENDIF."""

    depth: int
    fix: Fix
    has_else: bool = False


class Place(NamedTuple):
    """Where a statement stands in its file: the line it starts on and its index among that line's statements.

    The index counts the statements of ``LineFacts.statements``, so the body of an
    ``IF .. THEN`` counts after its ``IF``. Tools key what they know about a
    statement by its place: the syntax objects are shared by every line of the
    same text (see ``mintlang.syntax.parser``), so they can never name one.
    """

    line: int
    index: int


@record
class Block:
    """A matched (or unclosed) block, by the places of its statements; the LSP folds it, the runtime compiles it."""

    kind: BlockKind
    opener: Place
    middle: Place | None  # the ELSE of an IF block
    closer: Place | None  # None when never closed


@record
class Structure:
    blocks: tuple[Block, ...]
    diagnostics: tuple[Diagnostic, ...]


@record(frozen=False)
class _Open:
    kind: BlockKind
    opener: Place
    span: Span  # of the opener, in its file: where its diagnostics go
    middle: Place | None = None
    reported: bool = False  # an error already tells of this block: its opener is broken, or a closer mismatched
    over: str | None = None  # the nesting limit exceeded with this block open (``nesting_problem``)


_OPENING_WORDS = {"REPEAT": BlockKind.REPEAT, "LOOP": BlockKind.LOOP, "STARTUP": BlockKind.STARTUP}


def opener_kind(statement: n.Statement) -> BlockKind | None:
    """The kind of block ``statement`` opens, if it opens one."""
    kind = type(statement)
    if kind is n.BlockWord:
        return _OPENING_WORDS.get(statement.word)  # type: ignore[union-attr]
    if kind is n.IfDo:
        return BlockKind.IF
    if kind is n.EventBlock:
        return BlockKind.EVENT
    if kind is n.For:
        return BlockKind.FOR
    if kind is n.While:
        return BlockKind.WHILE
    if kind is n.SyntaxError_ and statement.opens is not None:  # type: ignore[union-attr]
        return BlockKind(statement.opens)  # type: ignore[union-attr]
    return None


def closer_kind(statement: n.Statement) -> BlockKind | None:
    """The kind of block ``statement`` closes, if it closes one: a broken closer (``NEXT a``) too, and another
    BASIC's word for one (``WEND``), as the matcher counts them, so a tool following the blocks sees the same
    ones as the compiler's stack."""
    kind = type(statement)
    if kind is n.Until:
        return BlockKind.REPEAT
    if kind is n.BlockWord:
        word = statement.word  # type: ignore[union-attr]
    elif kind is n.BareName:
        word = OTHER_BASICS.get(statement.name.text.upper(), "")  # type: ignore[union-attr]
    elif kind is n.SyntaxError_ and statement.closes is not None:  # type: ignore[union-attr]
        word = statement.closes  # type: ignore[union-attr]
        if word == "UNTIL":
            return BlockKind.REPEAT
    else:
        return None
    closed = _CLOSERS.get(word)
    return closed[0] if closed is not None else None


_error = mint_error


class _Matcher:
    """The compiler's block stack over one file."""

    def __init__(self, limits: NestingLimits, dialect: Dialect) -> None:
        self.limits = limits
        # a Mint v3 controller stops on the block one too deep when it runs it (V3-14), v4's compiler before
        self.deep_when_run = True if dialect is Dialect.V3 else None
        self.words = _MINTMT_WORDS if dialect is Dialect.MINTMT else {}
        self.stack: list[_Open] = []
        self.open = dict.fromkeys(BlockKind, 0)
        self.events: dict[Event, int] = {}  # each MintMT event handled, with the line of its Event block
        self.startup: int | None = None  # the line of the MintMT Startup block
        self.blocks: list[Block] = []
        self.diagnostics: list[Diagnostic] = []
        self.bare_then: _BareThen | None = None  # the last IF .. THEN with nothing after THEN

    def statement(self, statement: n.Statement, line: n.PlacedLine, index: int) -> None:
        """One statement of ``BLOCK_STATEMENTS``, the ``index``-th of its line."""
        kind = opener_kind(statement)
        place = Place(line.number, index)
        if type(statement) is n.IfThen:
            then = _then_written(statement, line.syntax) if not statement.body else None  # type: ignore[union-attr]
            if then is not None:
                self.bare_then = _BareThen(len(self.stack), Fix("Change THEN to DO", (Edit(line.span(then), "DO"),)))
        elif type(statement) is n.BareName:
            # WEND, as other BASICs close WHILE: its error 3007 names ENDW and is the one error, so it closes the
            # block on top if it is the one ENDW would close, and is no mismatch if it is not
            closed = closer_kind(statement)
            if closed is not None and self.stack and self.stack[-1].kind is closed:
                self.close(closed, place, line.span(statement.span), 0, "")
        elif kind is not None:
            if kind in _TOP_LEVEL:
                self._top_level(statement, kind, line)
            broken = type(statement) is n.SyntaxError_
            self.stack.append(_Open(kind, place, line.span(statement.span), reported=broken))
            self.open[kind] += 1
            problem = nesting_problem(self.open, self.limits)
            self.stack[-1].over = problem
            # once where a limit is crossed, not again for each block nested deeper (the compiler stops there)
            if problem is not None and (len(self.stack) < 2 or self.stack[-2].over != problem):
                self.diagnostics.append(
                    _error(2015, line.span(statement.span), problem, at_run_time=self.deep_when_run)
                )
        elif isinstance(statement, n.Until) or (isinstance(statement, n.SyntaxError_) and statement.closes == "UNTIL"):
            self.close(
                BlockKind.REPEAT,
                place,
                line.span(_first_word(statement.span, line.syntax)),
                2013,
                "UNTIL without REPEAT",
            )
        elif isinstance(statement, n.SyntaxError_) and statement.closes in _CLOSERS:
            self._closer(statement.closes, place, line.span(_first_word(statement.span, line.syntax)))  # type: ignore[arg-type]
        elif isinstance(statement, n.BlockWord) and statement.word == "ELSE":
            top = self.stack[-1] if self.stack else None
            if top is None or top.kind is not BlockKind.IF or top.middle is not None:
                self.diagnostics.append(
                    _error(2011, line.span(statement.span), "ELSE without IF .. DO", fixes=self._do("ELSE"))
                )
            else:
                top.middle = place
        elif isinstance(statement, n.BlockWord) and statement.word in _CLOSERS:
            self._closer(statement.word, place, line.span(statement.span))

    def spelled(self, word: str) -> str:
        """A block word as the program's dialect writes it."""
        return self.words.get(word, word)

    def _closer(self, word: str, place: Place, span: Span) -> None:
        expected, code, closer, opener = _CLOSERS[word]
        self.close(expected, place, span, code, f"{self.spelled(closer)} without {self.spelled(opener)}")

    def _top_level(self, statement: n.Statement, kind: BlockKind, line: n.PlacedLine) -> None:
        """MintMT's Event and Startup blocks stand alone, an Event names an event, and a program has one Startup
        block, the one the controller runs at power-up (004:89, 128; MT-6, MT-13)."""
        span = line.span(statement.span)
        if self.stack:
            inner = self.stack[-1]
            where = f"the {inner.kind.value} block of line {inner.opener.line}"
            detail = f"{kind.value} blocks stand alone: this one is inside {where}"
            self.diagnostics.append(_error(2003, span, detail))
        if type(statement) is n.EventBlock:
            self._event(statement.name, line)
        elif self.startup is None:
            self.startup = line.number
        else:
            detail = f"a second Startup block: the controller runs the block of line {self.startup} at power-up"
            self.diagnostics.append(_error(2003, span, detail))

    def _event(self, name: n.Name, line: n.PlacedLine) -> None:
        """An Event names an event (comms locations 1 to 5 raise one, 002:19), and only one block handles it."""
        event = event_of(name.text, Dialect.MINTMT)
        span = line.span(name.span)
        if event is None or (event.kind is EventKind.COMMS and event.number not in _COMMS_EVENTS):
            detail = f"{name.text} is no event (MOVEBUFFERLOW, ONERROR, TIMER, STOP, COMMS1..5, INx, FASTINx, CANx)"
            meant = closest(name.text.upper(), _NAMED_EVENTS) if event is None else None  # not Comms9
            fixes = (Fix.replace(span, meant),) if meant is not None else ()
            self.diagnostics.append(
                _error(2003, span, f"{detail}; {did_you_mean(meant)}" if meant else detail, fixes=fixes)
            )
            return
        first = self.events.setdefault(event, line.number)
        if first != line.number:
            detail = f"a second Event {name.text} block: the event's handler is the block of line {first}"
            self.diagnostics.append(_error(2003, span, detail))

    def _do(self, word: str) -> tuple[Fix, ...]:
        """Writing DO for the THEN of the last bare IF .. THEN at the depth a stray ELSE or ENDIF stands at, while
        the block that DO would open could take it: its first ELSE and its first ENDIF, never a second ELSE
        (000:18983-18999) nor an ENDIF after the one that would close it."""
        bare = self.bare_then
        if bare is None or bare.depth != len(self.stack) or (word == "ELSE" and bare.has_else):
            return ()
        self.bare_then = bare._replace(has_else=True) if word == "ELSE" else None
        return (bare.fix,)

    def close(self, kind: BlockKind, closer: Place, span: Span, code: int, message: str) -> None:
        stack = self.stack
        if not stack or stack[-1].kind is not kind:
            if stack:
                inner = self.spelled(stack[-1].kind.value)
                message += f" (the innermost open block is {inner} on line {stack[-1].opener.line})"
            for opened in stack:  # the compiler stops here: what it had open is not reported again
                opened.reported = True
            fixes = self._do("ENDIF") if kind is BlockKind.IF else ()
            self.diagnostics.append(_error(code, span, message, fixes=fixes))
            return
        top = stack.pop()
        self.open[kind] -= 1
        self.blocks.append(Block(kind, top.opener, top.middle, closer))
        if self.bare_then is not None and self.bare_then.depth > len(stack):  # DO there reaches no later ELSE
            self.bare_then = None

    def finish(self) -> Structure:
        for unclosed in self.stack:
            self.blocks.append(Block(unclosed.kind, unclosed.opener, unclosed.middle, None))
            if unclosed.reported:
                continue
            word, code = _CLOSING[unclosed.kind]
            detail = f"this {self.spelled(unclosed.kind.value)} block is never closed with {self.spelled(word)}"
            self.diagnostics.append(_error(code, unclosed.span, detail))
        self.blocks.sort(key=lambda block: block.opener)
        return Structure(tuple(self.blocks), tuple(self.diagnostics))


def _first_word(span: Span, line: n.LineSyntax) -> Span:
    """The word ``span`` begins with: a closer's error is about its word, not the condition or variable after
    it (``UNTIL a > 1``, ``NEXT i``)."""
    text = line.text
    end, stop = span.start, min(span.end, len(text))
    while end < stop and in_a_word(text[end]):
        end += 1
    return Span(span.start, end) if end > span.start else span


def _then_written(statement: n.IfThen, line: n.LineSyntax) -> Span | None:
    """Where the THEN of ``statement`` is written in its line (not from a macro's text)."""
    text = line.text
    start = statement.condition.span.end
    while start < len(text) and text[start] in " \t":
        start += 1
    return Span(start, start + 4) if text[start : start + 4].upper() == "THEN" else None


def block_key(statement: n.Statement, line: n.LineSyntax) -> Hashable:
    """What the matcher reads of a block statement, but for its span (where the errors about it go):
    equal keys at equal places match the same blocks."""
    kind = type(statement)
    if kind is n.IfThen:
        return kind, None if statement.body else _then_written(statement, line)  # type: ignore[union-attr]
    if kind is n.BlockWord:
        return kind, statement.word  # type: ignore[union-attr]
    if kind is n.SyntaxError_:
        return kind, statement.opens, statement.closes  # type: ignore[union-attr]
    if kind is n.EventBlock:
        return kind, statement.name  # type: ignore[union-attr]
    if kind is n.BareName:
        return kind, closer_kind(statement)
    return kind


def match_blocks(
    lines: Iterable[tuple[n.PlacedLine, LineFacts]], controller: ControllerProfile, dialect: Dialect = Dialect.V4
) -> Structure:
    """Match the blocks of one file and check the nesting limits; errors name blocks as ``dialect`` writes them."""
    matcher = _Matcher(nesting_of(controller, dialect), dialect)
    for line, facts in lines:
        if not facts.kinds.isdisjoint(BLOCK_STATEMENTS):  # most lines open and close nothing
            for index, statement in enumerate(facts.statements):
                if type(statement) in BLOCK_STATEMENTS:
                    matcher.statement(statement, line, index)
    return matcher.finish()


def nesting_problem(open_: Mapping[BlockKind, int], limits: NestingLimits) -> str | None:
    """What limit the blocks open now exceed, if any (``open_`` counts them by kind); the runtime's stack too."""
    ifs, fors = open_[BlockKind.IF], open_[BlockKind.FOR]
    others = open_[BlockKind.REPEAT] + open_[BlockKind.WHILE] + open_[BlockKind.LOOP]
    if ifs > limits.if_blocks:
        return f"IF blocks nested more than {limits.if_blocks} deep"
    if fors > limits.for_loops:
        return f"FOR loops nested more than {limits.for_loops} deep"
    if others > limits.other_loops:
        return f"WHILE, LOOP and REPEAT blocks nested more than {limits.other_loops} deep together"
    if others + ifs > limits.loops_and_ifs:
        return f"loops and IF blocks nested more than {limits.loops_and_ifs} deep together"
    return None
