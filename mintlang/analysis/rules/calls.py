"""GOSUB nesting: subroutines that call themselves, and chains of calls deeper than the controller allows.

Each GOSUB nests one level until its RETURN. The controller allows 100 levels
(50 on NextMove PC, 3.9) and stops with error 2015 beyond them. A routine that
calls itself, directly or through others, nests one level more with every
call: W115, at the GOSUB that closes the circle. A chain of calls from the
main program or an event handler that is deeper than the limit: W116. Both
are warnings: the calls may be conditional, and the depth is only reached
when the program runs.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import field

from mintlang.analysis.findings import Finding, own
from mintlang.analysis.rules.flow import subroutines
from mintlang.analysis.traversal import Facts
from mintlang.controllers import nesting_of
from mintlang.diagnostics import Span
from mintlang.dialect import Dialect
from mintlang.records import record
from mintlang.semantic.events import event_of
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n

_MAIN = ""  # the main program: no label starts it


@record
class _Call:
    target: str  # identity of the label called
    line: n.PlacedLine
    statement: n.Jump


@record(frozen=False)
class _Graph:
    """Which routine calls which: the main program and every subroutine of one file."""

    calls: dict[str, list[_Call]] = field(default_factory=dict)
    blocks: list[str] = field(default_factory=list)  # MintMT's Event and Startup blocks: routines of their own
    longest: dict[str, int] = field(default_factory=dict)  # levels of GOSUB a routine's calls can nest
    recursive: list[_Call] = field(default_factory=list)

    def depth(self, routine: str, open_: list[str]) -> int:
        """The longest chain of calls below ``routine``; calls back into ``open_`` are recursion."""
        if routine in self.longest:
            return self.longest[routine]
        open_.append(routine)
        deepest = 0
        for call in self.calls.get(routine, ()):
            if call.target in open_:
                self.recursive.append(call)
            elif call.target in self.calls:
                deepest = max(deepest, 1 + self.depth(call.target, open_))
            else:
                deepest = max(deepest, 1)  # a label without calls, or none at all (3004 says so)
        open_.pop()
        self.longest[routine] = deepest
        return deepest


def check(facts: Facts) -> Iterator[Finding]:
    model = facts.model
    dialect = model.program.dialect
    limit = nesting_of(model.controller, dialect).gosub
    allowing = "Mint v3" if dialect is Dialect.V3 else model.controller.title
    for unit, _ in model.documents():
        graph = _graph(unit, facts, blocks=dialect is Dialect.MINTMT)
        events = (label for label in graph.calls if label and event_of(label, dialect) is not None)
        roots = [_MAIN, *events, *graph.blocks]
        for root in roots:
            if graph.depth(root, []) > limit:
                call = next(call for call in graph.calls[root] if _levels(graph, call) == graph.longest[root])
                detail = (
                    f"GOSUB {call.statement.label.text} starts calls nested {graph.longest[root]} levels deep; "
                    f"{allowing} allows {limit} (error 2015 when it runs)"
                )
                yield Finding(unit, own("W116", call.line.span(call.statement.span), detail))
        reported: set[tuple[int, Span]] = set()
        for call in graph.recursive:  # once each place, in the order found
            place = (call.line.number, call.statement.span)
            if place in reported:
                continue
            reported.add(place)
            detail = f"#{call.statement.label.text} is called again before it returns: every call nests deeper"
            yield Finding(unit, own("W115", call.line.span(call.statement.span), detail))


def _levels(graph: _Graph, call: _Call) -> int:
    return 1 + graph.longest.get(call.target, 0)


def _graph(unit: Unit, facts: Facts, *, blocks: bool) -> _Graph:
    """The calls of each routine of one file: a routine runs from its label to the next subroutine's, and
    a MintMT ``Event`` or ``Startup`` block is one of its own, up to its end, after which the routine
    around it goes on (the block is stepped over, MT-7)."""
    entries = subroutines(unit, facts.model, facts)
    graph = _Graph({_MAIN: []})
    routine = around = _MAIN
    for file, line, indexed in facts.lines:
        if file is not unit:
            continue
        label = line.syntax.label
        if label is not None and label.identity in entries:
            routine = label.identity
            graph.calls.setdefault(routine, [])
        for statement in line.syntax.statements if blocks else ():
            opened = _block_opened(statement, line.number)
            if opened is not None:
                around, routine = routine, opened
                graph.calls[routine] = []
                graph.blocks.append(routine)
            elif type(statement) is n.BlockWord and statement.word in _BLOCK_ENDS:
                routine = around
        if n.Jump in indexed.kinds:
            for statement in indexed.statements:
                if type(statement) is n.Jump and statement.word == "GOSUB":
                    graph.calls[routine].append(_Call(statement.label.identity, line, statement))
    return graph


_BLOCK_ENDS = frozenset({"ENDEVENT", "ENDSTARTUP"})


def _block_opened(statement: n.Statement, number: int) -> str | None:
    """The routine a MintMT block opening on line ``number`` starts (no label can be spelt so), or None."""
    if type(statement) is n.EventBlock:
        return f"Event {statement.name.text} on line {number}"
    if type(statement) is n.BlockWord and statement.word == "STARTUP":
        return f"Startup on line {number}"
    return None
