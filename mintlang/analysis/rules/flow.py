"""Control flow a reader can get wrong: dead code, falling into subroutines, jumps out of blocks.

* Statements after END, RETURN, GOTO or EXIT that nothing can reach (W106).
  A lone END or RETURN right after an endless main loop is the manual's own
  program structure (line 279: "#main / LOOP .. ENDL / RETURN") and is not reported,
  nor a lone RETURN right after a subroutine's own END, the layout of the manual's
  #ONERROR handlers (000:4734-4736, 000:4793-4795: "END" then "RETURN").
  Nor is what the compiler does wherever it stands: a DEFINE (macros are substituted
  at compile time, 000:18494), an array's DIM (arrays are made and filled at compile
  time, "regardless of where they reside", 000:1104-1105) and a DIM that only declares
  (000:967-970); a variable's DIM with a value gives it at run time (000:1027-1033).
  The fix removes the whole unreachable run, blocks opened in it with their
  closers, and nothing that a block opened before it needs.
* Main program code that runs on into the first subroutine without END:
  its RETURN then fails with error 2010 (the manual's own example, 12.4).
  Reported at that RETURN as a warning: the file may be a fragment. A RETURN
  the main program itself reaches (ending it in place of END) is error 2010
  when it runs.
* A subroutine without RETURN that runs on into the next one (W107). A label
  that only GOTO reaches is a place in the code around it, not a subroutine.
* GOTO out of an event handler before its RETURN, or out of an open IF block or
  loop (W113): the handler or block is never closed, and done repeatedly this
  "will eventually" overflow the controller's stack (GOTO in 10.3). The overflow
  happens at run time, so the analyser only warns, once at the GOTO, naming the
  handler and every block it leaves open with its line.
* EXIT outside any loop of its subroutine or handler: error 2003 when it runs.
* GOTO from the main program into a subroutine or event handler (a MintMT Event block), when the code it
  reaches returns: that RETURN (End Event) has no GOSUB to return to, error 2010 when it runs; reported
  at the GOTO, which is what is wrong.

An endless loop (LOOP, WHILE 1, REPEAT .. UNTIL 0) that no EXIT or GOTO leaves
never falls through: a main program ending in one needs no END.

MintMT's ``Event`` and ``Startup`` blocks are entered by the controller, never by
the code around them: each is followed as an entry point of its own, and the
flow around it goes on after it as if it were not there.
"""

from __future__ import annotations

import math
from bisect import bisect_left
from collections.abc import Iterable, Iterator
from dataclasses import replace
from typing import NamedTuple

from mintlang.analysis.findings import Finding, mint_error, own
from mintlang.analysis.traversal import Facts
from mintlang.diagnostics import Diagnostic, Edit, Fix, Severity, Span
from mintlang.dialect import Dialect
from mintlang.records import record
from mintlang.semantic.blocks import LOOPS, Block, BlockKind, closer_kind, opener_kind
from mintlang.semantic.constants import constant_value
from mintlang.semantic.events import event_of
from mintlang.semantic.index import LineFacts
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.symbols import Unit
from mintlang.syntax import nodes as n
from mintlang.syntax.lexer import comment_at
from mintlang.syntax.parser import Document

_TERMINATORS = frozenset({"END", "RETURN", "EXIT"})
_LAST_WORDS = frozenset({"END", "RETURN"})
_RETURN_WORD = frozenset({"RETURN"})
_NO_WORDS: frozenset[str] = frozenset()
# What changes the flow; a line of other statements only runs, when it can be reached at all. A statement
# that does not parse may still open or close a block (``FOR loop = ..``, ``NEXT i``, ``WEND``), as the
# matcher counts it.
_FLOW_STATEMENTS = frozenset(
    {n.BlockWord, n.Jump, n.IfDo, n.IfThen, n.While, n.For, n.Until, n.EventBlock, n.SyntaxError_, n.BareName}
)
_SEPARATE_BLOCKS = {"STARTUP": "ENDSTARTUP"}  # MintMT blocks besides Event .. End Event


def _ends_flow(statement: n.Statement) -> bool:
    kind = type(statement)
    if kind is n.BlockWord:
        return statement.word in _TERMINATORS  # type: ignore[union-attr]
    return kind is n.Jump and statement.word == "GOTO"  # type: ignore[union-attr]


def _compiled(statement: n.Statement) -> bool:
    """A DEFINE, or a DIM with nothing to do at run time: the compiler acts on it wherever it stands."""
    kind = type(statement)
    return kind is n.Define or (kind is n.Dim and (statement.size is not None or not statement.values))  # type: ignore[union-attr]


def _receives_flow(statement: n.Statement) -> bool:
    """A loop's closer, reached from elsewhere in its block (by EXIT, or the pass that ends it)."""
    return closer_kind(statement) in LOOPS


def check(facts: Facts) -> Iterator[Finding]:
    model = facts.model
    for unit, document in model.documents():
        starts = subroutines(unit, model, facts)
        flow = _Flow(unit, document, starts)
        yield from flow.findings(facts.lines.of(unit))
        yield from _jumps_out_of_blocks(unit, document, model, facts, flow)
        yield from _jumps_into_routines(unit, document, model, facts, flow)


def runs_off_the_end(unit: Unit, facts: Facts) -> bool:
    """Whether the controller can run past the file's last line: no END, RETURN, GOTO or endless loop stops
    it there, so code added after it would run as part of what comes before."""
    model = facts.model
    flow = _Flow(unit, model.document(unit), subroutines(unit, model, facts))
    flow.findings(facts.lines.of(unit))
    return flow.reachable


def subroutines(unit: Unit, model: SemanticModel, facts: Facts) -> frozenset[str]:
    """Labels that start a subroutine: called by GOSUB, called by the controller, or never jumped to at all."""
    gosubs = {
        statement.label.identity  # type: ignore[union-attr]
        for file, _, statement in facts.statements(n.Jump)
        if file is unit and statement.word == "GOSUB"  # type: ignore[union-attr]
    }
    return frozenset(
        identity
        for identity, symbol in model.symbols.labels[unit].items()
        if identity in gosubs or not symbol.references or event_of(symbol.name, model.program.dialect) is not None
    )


_OPENERS = frozenset({n.IfDo, n.For, n.While})
_OPENING_WORDS = frozenset({"LOOP", "REPEAT"})
_CLOSING_WORDS = frozenset({"ENDIF", "NEXT", "ENDW", "ENDL", "ELSE"})  # ELSE closes its IF's first branch


def _nesting(statement: n.Statement) -> int:
    """+1 for a statement that opens a block, -1 for one that closes a branch or a block, else 0."""
    kind = type(statement)
    if kind in _OPENERS or (kind is n.BlockWord and statement.word in _OPENING_WORDS):  # type: ignore[union-attr]
        return 1
    if kind is n.Until or (kind is n.BlockWord and statement.word in _CLOSING_WORDS):  # type: ignore[union-attr]
        return -1
    if kind is n.SyntaxError_:
        return 1 if statement.opens else -1 if statement.closes else 0  # type: ignore[union-attr]
    return 0


def _is_else(statement: n.Statement) -> bool:
    return type(statement) is n.BlockWord and statement.word == "ELSE"  # type: ignore[union-attr]


@record(frozen=False)
class _DeadRun:
    """Statements that can never run, from a W106 on: what its fix removes.

    Blocks opened in the run are taken whole, with their closers (an ELSE
    stays with its IF); a closer of a block opened before the run ends it,
    and so does a statement that runs outside the run's blocks.
    """

    finding: int  # the index of its W106 among the flow's findings
    start: int
    end: int
    depth: int = 0  # blocks opened in the run and not yet closed

    def take(self, statement: n.Statement, span: Span, runs: bool) -> bool:
        """Whether ``statement`` (at ``span`` in the file) belongs to the run; the run grows by it if so."""
        nesting = _nesting(statement)
        if self.depth == 0 and (runs or nesting < 0):
            return False
        if nesting > 0:
            self.depth += 1
        elif nesting < 0 and not _is_else(statement):
            self.depth -= 1
        self.end = span.end
        return True


_BLANKS = " \t"


def _removal(source: str, start: int, end: int) -> Edit:
    """Remove ``source[start:end]``: whole lines when nothing else is on them, else with the ``:`` that
    separates it from the statements kept; a comment after it stays on its line."""
    line_start = max(source.rfind("\n", 0, start), source.rfind("\r", 0, start)) + 1
    after = len(source) - len(source[end:].lstrip(_BLANKS))  # what follows on the last line
    if not source[line_start:start].strip(_BLANKS) and source[after : after + 1] in ("", "\r", "\n"):
        line_end = after + (2 if source.startswith("\r\n", after) else 1 if after < len(source) else 0)
        return Edit(Span(line_start, line_end), "")  # whole lines, with their line breaks
    if comment_at(source, after):  # a comment ends the line (a REM needs no colon): it stays on its line
        return Edit(Span(start, after), "")
    if source[after : after + 1] == ":":  # statements kept after it: the separator goes with the run
        return Edit(Span(start, len(source) - len(source[after + 1 :].lstrip(_BLANKS))), "")
    before = len(source[:start].rstrip(_BLANKS))  # statements kept before it, then ":"
    return Edit(Span(len(source[: before - 1].rstrip(_BLANKS)), end), "")


@record(frozen=False)
class _Loop:
    endless: bool  # LOOP, WHILE with a true constant, or a REPEAT that may end up endless
    left: bool = False  # an EXIT or GOTO inside may leave it


@record(frozen=False)
class _If:
    """An open IF .. DO: the code after ENDIF runs if either branch gets there."""

    entered: bool  # the IF .. DO itself can run
    through_then: bool | None = None  # the THEN branch runs to its end; None before the ELSE


class _State(NamedTuple):
    """Where the flow stands: kept around a MintMT Event or Startup block, which it does not enter."""

    reachable: bool
    reported: bool
    running: bool
    closing: frozenset[str]
    subroutine: n.Name | None
    falling_from_main: bool


class _Flow:
    """Follows one file top to bottom, as the controller runs it when nothing jumps."""

    def __init__(self, unit: Unit, document: Document, subroutines: frozenset[str]) -> None:
        self.unit = unit
        self.source = document.source
        self.dialect = document.dialect
        self.dead: _DeadRun | None = None
        self.subroutines = subroutines
        self.reachable = True
        self.reported = False  # one W106 per unreachable run
        self.closing = _NO_WORDS  # the lone words the manual's layout puts after what just stopped the flow
        self.running = False  # some statement has run since the last entry point
        self.subroutine: n.Name | None = None  # None while in the main program
        # Whether the code being followed is the main program's: after a stop, code that a GOTO's label reaches
        # is the main program's only when the main program jumps there; reached from a subroutine or a handler
        # (#ONERROR .. GOTO common), its RETURN is fine.
        self.main_from_the_top = True
        self.main_gotos: set[str] = set()  # the labels the main program jumps to
        self.main_jumps: list[tuple[n.PlacedLine, n.Jump]] = []  # its GOTOs, outside any MintMT block
        self.falling_from_main = False
        self.loops: list[_Loop] = []
        self.ifs: list[_If] = []
        self.around: _State | None = None  # the flow outside the MintMT Event or Startup block being followed
        self.startup = False  # in a MintMT Startup block: run at power-up, which no GOSUB called
        self.line = n.PlacedLine(0, 0, n.LineSyntax("", Span(0, 0), None, ()), "")  # the line being followed
        self.found: list[Finding] = []
        self.run_into: set[int] = set()  # the lines of the subroutine labels the code above them runs into
        self.endless: list[int] = []  # the lines closing an endless loop, past which nothing runs

    def findings(self, lines: Iterable[tuple[n.PlacedLine, LineFacts]]) -> list[Finding]:
        for line, facts in lines:
            self.line = line
            syntax = line.syntax
            if syntax.label is not None:
                self._end_dead_run()
                self._entry(syntax.label)
            if self.reachable and facts.kinds.isdisjoint(_FLOW_STATEMENTS) and self.dead is None:
                self.reported, self.running, self.closing = False, True, _NO_WORDS  # ran, and goes on
                continue
            for statement in syntax.statements:
                self._statement(statement)
        self._end_dead_run()
        return self.found

    def _end_dead_run(self) -> None:
        """Give the run's W106 its fix; none when a label or the end of the file comes inside a block it opened."""
        dead, self.dead = self.dead, None
        if dead is not None and dead.depth == 0 and dead.end > dead.start:
            finding = self.found[dead.finding]
            fix = Fix("Remove unreachable code", (_removal(self.source, dead.start, dead.end),))
            self.found[dead.finding] = Finding(finding.unit, replace(finding.diagnostic, fixes=(fix,)))

    def _dead(self, statement: n.Statement) -> None:
        """Grow the open dead run by ``statement``, whose reachability is now known, or end it."""
        if self.dead is not None and not self.dead.take(statement, self.line.span(statement.span), self.reachable):
            self._end_dead_run()

    def _report(self, diagnostic: Diagnostic) -> None:
        self.found.append(Finding(self.unit, diagnostic))

    def _entry(self, label: n.Name) -> None:
        if label.identity not in self.subroutines:  # a GOTO target: the same routine goes on
            self.main_from_the_top = (self.main_from_the_top and self.reachable) or label.identity in self.main_gotos
            self.reachable, self.reported = True, False
            return
        if self.reachable and self.running:
            self.run_into.add(self.line.number)
            if self.subroutine is None:
                self.falling_from_main = True
            else:
                detail = f"#{self.subroutine.text} has no RETURN here and runs on into #{label.text}"
                self._report(own("W107", self.line.span(label.span), detail))
        else:
            self.falling_from_main = False
        self.subroutine, self.reachable, self.reported, self.running = label, True, False, False

    def _separate_block(self, statement: n.Statement) -> bool:
        """Enter or leave a MintMT Event or Startup block: whether ``statement`` is one's first or last word."""
        word = statement.word if type(statement) is n.BlockWord else None  # type: ignore[union-attr]
        if type(statement) is n.EventBlock or word in _SEPARATE_BLOCKS:
            self._end_dead_run()
            self.around = self._state()
            self.startup = word in _SEPARATE_BLOCKS
            self._restore(_State(True, False, False, False, None, False))
            return True
        if word in ("ENDEVENT", *_SEPARATE_BLOCKS.values()) and self.around is not None:
            self._end_dead_run()
            # dead code after the block is a run of its own: the block between is live, and no fix removes it
            self._restore(self.around._replace(reported=False))
            self.around, self.startup = None, False
            return True
        return False

    def _state(self) -> _State:
        return _State(
            self.reachable,
            self.reported,
            self.running,
            self.closing,
            self.subroutine,
            self.falling_from_main,
        )

    def _restore(self, state: _State) -> None:
        self.reachable, self.reported, self.running, self.closing = state[:4]
        self.subroutine, self.falling_from_main = state.subroutine, state.falling_from_main

    def _statement(self, statement: n.Statement) -> None:
        kind = type(statement)
        if self.dialect is Dialect.MINTMT and self._separate_block(statement):
            return
        if not self.reachable and _compiled(statement):  # no dead code, and no part of a run to remove
            self._end_dead_run()
            self.reported = False
            return
        if kind not in _FLOW_STATEMENTS and self.reachable:  # runs, and changes nothing
            self._dead(statement)
            self.reported, self.running, self.closing = False, True, _NO_WORDS
            return
        if_bound = self._if_bounds(statement)  # ELSE and ENDIF are never dead code themselves
        if _receives_flow(statement):
            self.reachable = True
        elif not (if_bound or self.reachable or self.reported or self._closes_main_loop(statement)):
            self._end_dead_run()
            span = self.line.span(statement.span)
            self._report(own("W106", span, "this code can never run"))
            self.dead = _DeadRun(len(self.found) - 1, span.start, span.start)
            self.reported = True
        self._dead(statement)
        self.closing = _NO_WORDS
        if self.reachable:
            self.reported, self.running = False, True
        if kind is n.IfThen:
            for inner in n.walk_statements((statement,)):
                self._jumps(inner)
        elif kind is n.BlockWord or kind is n.Jump:
            self._jumps(statement)
        self._loop_bounds(statement)
        if _ends_flow(statement):
            self.reachable = False
            self.falling_from_main = False
            if self._ends_subroutine(statement):
                self.closing = _RETURN_WORD

    def _jumps(self, statement: n.Statement) -> None:
        """EXIT, GOTO and RETURN, also inside IF .. THEN."""
        if isinstance(statement, n.BlockWord) and statement.word == "EXIT":
            if not self.loops:
                # NM-8: EXIT leaves a loop of its own subroutine or handler, never a caller's; with none
                # it is error 2003 when it runs (the guide names no number for a misplaced loop word)
                detail = "EXIT is not inside a FOR, REPEAT, WHILE or LOOP of its own subroutine or handler"
                self._report(mint_error(2003, self.line.span(statement.span), detail, at_run_time=True))
            else:
                self.loops[-1].left = True
        elif isinstance(statement, n.Jump) and statement.word == "GOTO":
            for loop in self.loops:
                loop.left = True
            if self.subroutine is None and self.main_from_the_top:
                self.main_gotos.add(statement.label.identity)
                if self.around is None:
                    self.main_jumps.append((self.line, statement))
        elif isinstance(statement, n.BlockWord) and statement.word == "RETURN":
            self._return(statement)

    def _return(self, statement: n.BlockWord) -> None:
        """A RETURN of the main program, or of a MintMT Startup block: no GOSUB called it (2010, 000:18965-18978)."""
        span = self.line.span(statement.span)
        if self.falling_from_main:
            into = self.subroutine.text if self.subroutine else ""
            detail = f"the main program has no END and runs on into #{into}, so this RETURN has no GOSUB to return to"
            self._report(mint_error(2010, span, detail, severity=Severity.WARNING))
            self.falling_from_main = False
        elif self.subroutine is None and self.reachable and self.startup:
            detail = "this RETURN is in the Startup block, which the controller runs at power-up and no GOSUB called"
            self._report(mint_error(2010, span, detail))
        elif self.subroutine is None and self.main_from_the_top and self.reachable and self.around is None:
            detail = "this RETURN is in the main program, which no GOSUB called: end the main program with END"
            self._report(mint_error(2010, span, detail))

    def _closes_main_loop(self, statement: n.Statement) -> bool:
        """A lone END or RETURN straight after an endless loop, or RETURN after a subroutine's END: the manual's
        program structure."""
        return type(statement) is n.BlockWord and statement.word in self.closing  # type: ignore[union-attr]

    def _ends_subroutine(self, statement: n.Statement) -> bool:
        """An END at the top level of a subroutine or handler, which the manual closes with a RETURN all the same."""
        top = not (self.loops or self.ifs)
        return top and self.subroutine is not None and type(statement) is n.BlockWord and statement.word == "END"  # type: ignore[union-attr]

    def _if_bounds(self, statement: n.Statement) -> bool:
        """Follow IF .. DO, ELSE and ENDIF; True for ELSE and ENDIF, which are never dead code themselves."""
        if opener_kind(statement) is BlockKind.IF:
            self.ifs.append(_If(entered=self.reachable))
            return False
        closes = closer_kind(statement) is BlockKind.IF
        if not closes and not (type(statement) is n.BlockWord and statement.word == "ELSE"):  # type: ignore[union-attr]
            return False
        if not self.ifs:  # a closer without IF (2011): reached from nowhere the flow knows
            self.reachable = True
            return True
        block = self.ifs[-1]
        if not closes:  # ELSE
            block.through_then = self.reachable
            self.reachable = block.entered  # the condition was false
        else:
            self.ifs.pop()
            skipped = block.entered if block.through_then is None else block.through_then
            self.reachable = self.reachable or skipped
        return True

    def _loop_bounds(self, statement: n.Statement) -> None:
        """Open and close loops, broken ones as the matcher counts them (a condition that does not parse makes
        no loop endless); after an endless loop nothing that follows runs."""
        dialect = self.dialect
        kind = type(statement)
        if opener_kind(statement) in LOOPS:
            if kind is n.BlockWord:  # LOOP, or REPEAT: endless only if UNTIL says so
                endless = True
            elif kind is n.While:
                endless = bool(constant_value(statement.condition, dialect))  # type: ignore[union-attr]
            else:  # FOR, or a broken opener
                endless = False
            self.loops.append(_Loop(endless=endless))
        elif closer_kind(statement) in LOOPS and self.loops:
            loop = self.loops.pop()
            if kind is n.Until:
                loop.endless = loop.endless and constant_value(statement.condition, dialect) == 0  # type: ignore[union-attr]
            elif kind is n.SyntaxError_:
                loop.endless = False
            self._close(loop)

    def _close(self, loop: _Loop) -> None:
        if loop.endless and not loop.left:
            self.endless.append(self.line.number)
            self.reachable = False
            self.closing = _LAST_WORDS
            self.falling_from_main = False


class _Handler(NamedTuple):
    """An event handler's lines (or a subroutine's, or a MintMT Event block's), from its label to its RETURN."""

    named: str  # "the event handler #IN1", "the subroutine #work", "the Event block"
    first: int
    last: float
    ending: str = "RETURN"  # the word that returns from it


def _says(line: n.PlacedLine, word: str) -> bool:
    """Whether ``line`` has the one-word statement ``word`` of its own (not in an IF .. THEN)."""
    return any(isinstance(statement, n.BlockWord) and statement.word == word for statement in line.syntax.statements)


def _handlers(
    unit: Unit, document: Document, model: SemanticModel, starts: frozenset[str], *, subroutines: bool = False
) -> list[_Handler]:
    """The event handlers of the file (with ``subroutines``, every subroutine too), each up to its first RETURN
    outside its blocks, or else up to the next subroutine (a label only GOTO reaches before that RETURN is a
    place inside the handler)."""
    blocks = model.structures[unit].blocks
    dialect = model.program.dialect
    found: list[_Handler] = []
    open_handler: _Handler | None = None
    for line in document.placed:
        label = line.syntax.label
        if label is not None and label.identity in starts:
            if open_handler is not None:
                found.append(open_handler._replace(last=line.number - 1))
            event = event_of(label.text, dialect) is not None
            named = f"the event handler #{label.text}" if event else f"the subroutine #{label.text}"
            open_handler = _Handler(named, line.number, math.inf) if event or subroutines else None
        if (
            open_handler is not None
            and _says(line, "RETURN")
            and not any(_contains(block, line.number) for block in blocks)
        ):
            found.append(open_handler._replace(last=line.number))
            open_handler = None
    return found if open_handler is None else [*found, open_handler]


# MintMT's blocks the controller enters, whose code is a routine's own, not a block's inside it (MT-7)
_ENTRY_BLOCKS = frozenset({BlockKind.EVENT, BlockKind.STARTUP})
_RETURNING = frozenset({"RETURN", "ENDEVENT"})  # End Event returns from its block, as RETURN from a handler


# Where code run from a label settles: it returns (True), stops for good (False), or jumps to a label (its identity).
Outcome = bool | str


def _outcomes(unit: Unit, document: Document, model: SemanticModel, facts: Facts, flow: _Flow) -> dict[int, Outcome]:
    """The lines where code run from a label settles: a RETURN, conditional or not, or a subroutine the code above
    runs into (which returns); an END outside any block, or the end of an endless loop, past which nothing runs;
    a GOTO outside any block, which goes where its label is."""
    blocks = [block for block in model.structures[unit].blocks if block.kind not in _ENTRY_BLOCKS]
    returns = {
        line.number
        for file, line, statement in facts.statements(n.BlockWord)
        if file is unit and statement.word in _RETURNING  # type: ignore[union-attr]
    }
    found: dict[int, Outcome] = dict.fromkeys(flow.endless, False)
    for line in document.placed:
        number = line.number
        if number in returns or number in flow.run_into:
            found[number] = True
        elif not any(_contains(block, number) for block in blocks):
            if _says(line, "END"):
                found[number] = False
            elif (jump := next((s for s in line.syntax.statements if _is_goto(s)), None)) is not None:
                found[number] = jump.label.identity  # type: ignore[union-attr]
    return dict(sorted(found.items()))


def _is_goto(statement: n.Statement) -> bool:
    return type(statement) is n.Jump and statement.word == "GOTO"  # type: ignore[union-attr]


def _returns_from(target: int, outcomes: dict[int, Outcome], labels: dict[str, int]) -> bool:
    """Whether the code at the label of line ``target`` returns (a handler's shared exit), rather than ending the
    program, looping for good or running on to the file's end as a main program does; GOTOs are followed."""
    lines = list(outcomes)
    seen: set[int] = set()
    while target not in seen:
        seen.add(target)
        place = bisect_left(lines, target)
        if place == len(lines):
            return False
        outcome = outcomes[lines[place]]
        if not isinstance(outcome, str):
            return outcome
        if outcome not in labels:
            return False
        target = labels[outcome]
    return False  # jumps round in a circle


def _jumps_out_of_blocks(
    unit: Unit, document: Document, model: SemanticModel, facts: Facts, flow: _Flow
) -> Iterator[Finding]:
    """W113: a GOTO out of an event handler, IF block or loop (000:11199-11215), each of which stays on the stack."""
    gotos = [
        (line, statement)
        for file, line, statement in facts.statements(n.Jump)
        if file is unit and statement.word == "GOTO"
    ]
    if not gotos:
        return
    blocks = model.structures[unit].blocks
    handlers = _handlers(unit, document, model, flow.subroutines)
    outcomes = _outcomes(unit, document, model, facts, flow) if handlers else {}
    labels = {line.syntax.label.identity: line.number for line in document.placed if line.syntax.label is not None}
    for line, statement in gotos:
        target = labels.get(statement.label.identity)
        if target is None:
            continue
        left = [
            f"{handler.named} of line {handler.first}"
            for handler in handlers
            if handler.first <= line.number <= handler.last
            and not handler.first <= target <= handler.last
            and not _returns_from(target, outcomes, labels)  # a shared exit: its RETURN ends the handler
        ]
        left += _blocks_named(
            [block for block in blocks if _contains(block, line.number) and not _contains(block, target)]
        )
        if left:
            named = left[0] if len(left) == 1 else f"{', '.join(left[:-1])} and {left[-1]}"
            detail = f"GOTO {statement.label.text} leaves {named} open; done repeatedly, this overflows the stack"
            yield Finding(unit, own("W113", line.span(statement.span), f"{detail} (error 2015)"))


def _blocks_named(blocks: list[Block]) -> list[str]:
    """Each block a jump leaves, outermost first, by its kind and line: each one is left on the stack."""
    return [
        f"the {block.kind.value} block of line {block.opener.line}"
        for block in sorted(blocks, key=lambda block: block.opener)
    ]


def _contains(block: Block, line: int) -> bool:
    return block.opener.line <= line <= _last_line(block)


def _jumps_into_routines(
    unit: Unit, document: Document, model: SemanticModel, facts: Facts, flow: _Flow
) -> Iterator[Finding]:
    """2010: a GOTO of the main program into a subroutine, an event handler or a MintMT Event block, whose
    RETURN (End Event) the code reaches with no GOSUB to return to (000:18965-18967)."""
    if not flow.main_jumps:
        return
    routines = _handlers(unit, document, model, flow.subroutines, subroutines=True) + [
        _Handler("the Event block", block.opener.line, _last_line(block), "End Event")
        for block in model.structures[unit].blocks
        if block.kind is BlockKind.EVENT
    ]
    outcomes = _outcomes(unit, document, model, facts, flow)
    labels = {line.syntax.label.identity: line.number for line in document.placed if line.syntax.label is not None}
    for line, statement in flow.main_jumps:
        target = labels.get(statement.label.identity)
        entered = next(
            (
                routine
                for routine in routines
                if target is not None
                and routine.first <= target <= routine.last
                and not routine.first <= line.number <= routine.last
            ),
            None,
        )
        if entered is None or not _returns_from(target, outcomes, labels):  # type: ignore[arg-type]
            continue
        span = line.span(statement.span)
        jump = document.source[span.start : span.end].split()[0]  # GOTO, or MintMT's Goto, as written
        detail = (
            f"{jump} {statement.label.text} jumps from the main program into {entered.named} of line "
            f"{entered.first}, whose {entered.ending} then has no GOSUB to return to"
        )
        yield Finding(unit, mint_error(2010, span, detail))


def _last_line(block: Block) -> float:
    return block.closer.line if block.closer is not None else math.inf
