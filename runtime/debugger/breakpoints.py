"""Breakpoints on lines and on labels: where they bind, their condition, hit count and log message, and
whether a point hits one.

A breakpoint binds to the first statement of its line, or of the next line
holding a statement (a comment, a label, a blank line or a MintMT ``Event`` or
``Startup`` line runs nothing; an ELSE's jump, which ends the true branch, is on
its ENDIF's line): it stops each time that first statement is about to run, so once per pass over
a line like ``a = 1 : b = 2``, and not again while a blocked statement waits. Its condition is a Mint
expression (true when non-zero), read as it is set (one that does not read leaves the breakpoint
unverified, with why) and compiled against each run when first met; its hit condition counts the times the
condition held since it was set, and going back takes the count back with the
run: to what it was at the checkpoint the re-run starts from
(``checkpoints.py``), 0 for a breakpoint set since: ``5`` or ``== 5`` stops at the
fifth, ``>= 5`` (or ``> 4``) from the fifth on, ``< 3`` at the first two, ``% 3``
at every third. The editor sends all of a file's breakpoints whenever one
changes: those it sends unchanged keep their count. A log message prints
instead of stopping, each ``{expression}`` in it replaced by its value. A
breakpoint on a label (the editor's function breakpoints: ``TIMER``,
``ONERROR``, ``IN3``, a subroutine) stops where the label's code starts, so at
each event the handler serves. A breakpoint the request gets wrong (a line before
1, a condition that is not text) is unverified with why, and the request's others are set.
"""

from __future__ import annotations

import operator
import re
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

from mintlang.records import record
from mintlang.runtime.debugger.evaluation import Compiled, EvaluationError, Evaluator, run, shown
from mintlang.runtime.debugger.launch import Layout
from mintlang.syntax.nodes import identity

_HIT = re.compile(r"^\s*(==|>=|<=|>|<|%)?\s*(\d+)\s*$")
_TESTS: Mapping[str, Callable[[int, int], bool]] = {
    "==": operator.eq,
    ">=": operator.ge,
    "<=": operator.le,
    ">": operator.gt,
    "<": operator.lt,
    "%": lambda hits, every: every > 0 and hits % every == 0,
}
_PLACEHOLDER = re.compile(r"\{([^{}]*)\}")
FUNCTIONS = "functions"  # the group of breakpoints on labels
_TEXTS = ("condition", "hitCondition", "logMessage")  # a breakpoint's fields that are text


def hit_test(text: str) -> Callable[[int], bool]:
    """The test a hit condition makes of the hit count; ``ValueError`` for one it cannot read."""
    matched = _HIT.match(text)
    if matched is None:
        raise ValueError(f"hit condition {text!r}: write a count (5), or ==, >=, >, <=, < or % and a count")
    test = _TESTS[matched.group(1) or "=="]
    number = int(matched.group(2))
    return lambda hits: test(hits, number)


@dataclass(slots=True)
class Breakpoint:
    id: int
    unit: str  # "program" or "configuration"
    requested: int  # the line the editor asked for
    line: int | None  # where it binds; None when no statement is at or after the line
    pc: int | None  # the statement it stops before
    condition: str | None = None
    hit_condition: str | None = None
    log_message: str | None = None
    problem: str | None = None  # why it is not verified
    hits: int = 0
    compiled: Compiled | None = field(default=None, repr=False)  # the condition, for the run now going

    def as_dap(self, source: Mapping[str, Any] | None) -> dict[str, Any]:
        body: dict[str, Any] = {"id": self.id, "verified": self.problem is None}
        if source is not None:
            body["source"] = dict(source)
        if self.line is not None or self.requested:
            body["line"] = self.line if self.line is not None else self.requested
        if self.problem is not None:
            body["message"] = self.problem
        return body


@record
class Decision:
    """What reaching a breakpoint's line does: stop (with why, if its condition failed) or print a log line."""

    stop: bool
    log: str | None = None
    description: str | None = None


class Breakpoints:
    """The breakpoints of both files and of the program's labels, bound to the compiled application."""

    def __init__(self, layout: Layout) -> None:
        self.sites = layout.sites
        self.labels = layout.labels
        self.elses = {closer: pc for pc, closer in layout.endings.items()}  # an ENDIF -> the ELSE shown on its line
        self.expressions = layout.expressions
        self.refused = layout.refused
        self.next_id = 1
        self.generation = 0  # changes with every change of the breakpoints
        self.groups: dict[str, list[Breakpoint]] = {}  # a file's ("program", "configuration") or FUNCTIONS
        self.by_pc: dict[int, Breakpoint] = {}
        self.first_of_line: dict[tuple[str, int], int] = {}  # (unit, line) -> pc of its first statement
        for pc, site in enumerate(self.sites):
            if not site.declares and pc not in layout.endings:
                self.first_of_line.setdefault((site.unit, site.line), pc)

    def replace(self, unit: str, requests: Iterable[Mapping[str, Any]]) -> list[Breakpoint]:
        """The breakpoints of one file, as ``setBreakpoints`` gives them all at once."""
        lines = sorted(line for found_unit, line in self.first_of_line if found_unit == unit)
        placed = []
        for request in requests:
            requested = request.get("line")
            if not isinstance(requested, int) or isinstance(requested, bool) or requested < 1:
                why = f"a breakpoint's line is a whole number from 1, not {requested!r}"
                placed.append(self._made(request, unit, 0, None, why))
                continue
            line = next((line for line in lines if line >= requested), None)
            if line is None:
                placed.append(
                    self._made(
                        request, unit, requested, None, self._absent(f"no statement at or after line {requested}")
                    )
                )
            else:
                placed.append(self._made(request, unit, requested, self.first_of_line[(unit, line)]))
        return self._replaced(unit, placed)

    def replace_functions(self, requests: Iterable[Mapping[str, Any]]) -> list[Breakpoint]:
        """Breakpoints on labels (``setFunctionBreakpoints``): ``TIMER`` or ``#TIMER`` stops as ``#TIMER``
        starts, whether an event, a GOSUB or a GOTO runs it. A MintMT event block is known by its whole
        name, which may be longer than a label's ten significant characters (``MOVEBUFFERLOW``)."""
        placed = []
        for request in requests:
            name = str(request.get("name", "")).strip().lstrip("#")
            pc = self.labels.get(name.upper(), self.labels.get(identity(name)))
            if pc is None or pc >= len(self.sites):
                placed.append(
                    self._made(request, "program", 0, None, self._absent(f"the program has no label #{name}"))
                )
            else:
                placed.append(self._made(request, self.sites[pc].unit, self.sites[pc].line, pc))
        return self._replaced(FUNCTIONS, placed)

    def _absent(self, why: str) -> str:
        """Why a line or label is not found: in a program its compiler refuses, none is, whatever the text holds."""
        return f"does not compile: {self.refused}" if self.refused is not None else why

    def _made(
        self, request: Mapping[str, Any], unit: str, requested: int, pc: int | None, problem: str | None = None
    ) -> Breakpoint:
        line = self.sites[pc].line if pc is not None else None
        breakpoint_ = Breakpoint(self.next_id, unit, requested, line, pc)
        self.next_id += 1
        breakpoint_.condition = _text(request, "condition")
        breakpoint_.hit_condition = _text(request, "hitCondition")
        breakpoint_.log_message = _text(request, "logMessage")
        breakpoint_.problem = problem or _not_text(request) or self._unreadable(breakpoint_)
        return breakpoint_

    def _unreadable(self, breakpoint_: Breakpoint) -> str | None:
        """Why the breakpoint's condition or hit condition cannot be read, found as it is set rather than when
        the run first reaches it; a condition that reads but fails to evaluate still stops there and says why."""
        try:
            if breakpoint_.condition is not None and self.expressions is not None:
                self.expressions.read(breakpoint_.condition)
            if breakpoint_.hit_condition is not None:
                hit_test(breakpoint_.hit_condition)
        except EvaluationError as unreadable:
            return f"condition {breakpoint_.condition}: {unreadable}"
        except ValueError as unreadable:
            return str(unreadable)
        return None

    def _replaced(self, group: str, placed: list[Breakpoint]) -> list[Breakpoint]:
        """``placed`` instead of the group's breakpoints; those sent again unchanged keep their hit count."""
        counted = {_key(old): old.hits for old in self.groups.get(group, [])}
        for breakpoint_ in placed:
            breakpoint_.hits = counted.get(_key(breakpoint_), 0)
        self.groups[group] = placed
        self.generation += 1
        self.by_pc = {}
        for group_placed in self.groups.values():
            for breakpoint_ in group_placed:
                if breakpoint_.problem is None and breakpoint_.pc is not None:
                    self.by_pc.setdefault(breakpoint_.pc, breakpoint_)
                    if breakpoint_.pc in self.elses:  # on an ENDIF: the true branch leaves the block at its ELSE
                        self.by_pc.setdefault(self.elses[breakpoint_.pc], breakpoint_)
        return placed

    def start_run(self) -> None:
        """A new run begins: hit counts from zero, conditions compiled afresh against it when first met."""
        for breakpoint_ in self.by_pc.values():
            breakpoint_.hits = 0
            breakpoint_.compiled = None

    def hit_counts(self) -> dict[tuple[object, ...], int]:
        """Each breakpoint's hit count, by what makes a breakpoint sent again the same one: for a checkpoint."""
        return {_key(breakpoint_): breakpoint_.hits for breakpoint_ in self.by_pc.values()}

    def restore_hit_counts(self, counts: Mapping[tuple[object, ...], int]) -> None:
        """The run is taken back to a checkpoint: each count as it was there (0 for a breakpoint set since)."""
        for breakpoint_ in self.by_pc.values():
            breakpoint_.hits = counts.get(_key(breakpoint_), 0)

    def reached(self, pc: int, evaluator: Evaluator) -> Decision | None:
        """Control reaches ``pc``: None if no breakpoint is there or it does not hit, else what it does.

        A condition that cannot be compiled or evaluated stops there, and the stop says why."""
        breakpoint_ = self.by_pc.get(pc)
        if breakpoint_ is None:
            return None
        description = None
        if breakpoint_.condition is not None:
            try:
                if breakpoint_.compiled is None:
                    breakpoint_.compiled = evaluator.compile(breakpoint_.condition)
                if run(breakpoint_.compiled) == 0:
                    return None
            except EvaluationError as error:
                description = f"the condition {breakpoint_.condition} failed: {error}"
        breakpoint_.hits += 1
        if breakpoint_.hit_condition is not None and not hit_test(breakpoint_.hit_condition)(breakpoint_.hits):
            return None
        if breakpoint_.log_message is not None and description is None:
            return Decision(stop=False, log=interpolate(breakpoint_.log_message, evaluator))
        return Decision(stop=True, description=description)


def _text(request: Mapping[str, Any], name: str) -> str | None:
    """A breakpoint's ``condition``, ``hitCondition`` or ``logMessage``; None when absent, empty or not text."""
    value = request.get(name)
    return value if isinstance(value, str) and value else None


def _not_text(request: Mapping[str, Any]) -> str | None:
    """Why one breakpoint of a request is not set as sent: a condition, hit condition or log message that is
    not text leaves that breakpoint unverified, while the request's others are set."""
    for name in _TEXTS:
        value = request.get(name)
        if value is not None and not isinstance(value, str):
            return f"a breakpoint's {name!r} is text, not {value!r}"
    return None


def _key(breakpoint_: Breakpoint) -> tuple[int | None, str | None, str | None, str | None]:
    """What makes two breakpoints of a group the same one, sent again."""
    return breakpoint_.pc, breakpoint_.condition, breakpoint_.hit_condition, breakpoint_.log_message


def interpolate(message: str, evaluator: Evaluator) -> str:
    """A log message with each ``{expression}`` replaced by its value (or by why it has none)."""

    def value(match: re.Match[str]) -> str:
        try:
            return shown(evaluator.evaluate(match.group(1)))
        except EvaluationError as error:
            return f"<{error}>"

    return _PLACEHOLDER.sub(value, message) + "\n"
