"""Line breakpoints: where they bind, their condition, hit count and log message, and whether a point hits one.

A breakpoint binds to the first statement of its line, or of the next line
holding a statement (a comment, a label or a blank line runs nothing): it
stops each time that first statement is about to run, so once per pass over
a line like ``a = 1 : b = 2``, and not again while a blocked statement waits. Its condition is a Mint
expression (true when non-zero); its hit condition counts the times the
condition held since it was set, or since the run began again (stepping back
re-runs from the start, and counts from there): ``5`` or ``== 5`` stops at the
fifth, ``>= 5`` (or ``> 4``) from the fifth on, ``< 3`` at the first two, ``% 3``
at every third. The editor sends all of a file's breakpoints whenever one
changes: those it sends unchanged keep their count. A log message prints
instead of stopping, each ``{expression}`` in it replaced by its value.
"""

from __future__ import annotations

import operator
import re
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

from mintlang.runtime.debugger.evaluation import Compiled, EvaluationError, Evaluator, run, shown
from mintlang.runtime.interpreter.vm import Site

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
    condition: str | None = None
    hit_condition: str | None = None
    log_message: str | None = None
    problem: str | None = None  # why it is not verified
    hits: int = 0
    compiled: Compiled | None = field(default=None, repr=False)  # the condition, for the run now going

    def as_dap(self, source: Mapping[str, Any]) -> dict[str, Any]:
        body: dict[str, Any] = {"id": self.id, "verified": self.problem is None, "source": dict(source)}
        body["line"] = self.line if self.line is not None else self.requested
        if self.problem is not None:
            body["message"] = self.problem
        return body


@dataclass(frozen=True, slots=True)
class Decision:
    """What reaching a breakpoint's line does: stop (with why, if its condition failed) or print a log line."""

    stop: bool
    log: str | None = None
    description: str | None = None


class Breakpoints:
    """The breakpoints of both files, bound to the statements of the compiled application."""

    def __init__(self, sites: list[Site]) -> None:
        self.sites = sites
        self.next_id = 1
        self.generation = 0  # changes with every change of the breakpoints
        self.by_unit: dict[str, list[Breakpoint]] = {}
        self.by_pc: dict[int, Breakpoint] = {}
        self.first_of_line: dict[tuple[str, int], int] = {}  # (unit, line) -> pc of its first statement
        for pc, site in enumerate(sites):
            self.first_of_line.setdefault((site.unit, site.line), pc)

    def replace(self, unit: str, requests: Iterable[Mapping[str, Any]]) -> list[Breakpoint]:
        """The breakpoints of one file, as ``setBreakpoints`` gives them all at once."""
        lines = sorted(line for found_unit, line in self.first_of_line if found_unit == unit)
        counted = {_key(old): old.hits for old in self.by_unit.get(unit, [])}
        placed = []
        for request in requests:
            requested = int(request.get("line", 0))
            line = next((line for line in lines if line >= requested), None)
            breakpoint_ = Breakpoint(self.next_id, unit, requested, line)
            self.next_id += 1
            breakpoint_.condition = request.get("condition") or None
            breakpoint_.hit_condition = request.get("hitCondition") or None
            breakpoint_.log_message = request.get("logMessage") or None
            breakpoint_.hits = counted.get(_key(breakpoint_), 0)
            if line is None:
                breakpoint_.problem = f"no statement at or after line {requested}"
            elif breakpoint_.hit_condition is not None:
                try:
                    hit_test(breakpoint_.hit_condition)
                except ValueError as problem:
                    breakpoint_.problem = str(problem)
            placed.append(breakpoint_)
        self.by_unit[unit] = placed
        self.generation += 1
        self._index()
        return placed

    def _index(self) -> None:
        self.by_pc = {}
        for placed in self.by_unit.values():
            for breakpoint_ in placed:
                if breakpoint_.problem is None and breakpoint_.line is not None:
                    self.by_pc.setdefault(self.first_of_line[(breakpoint_.unit, breakpoint_.line)], breakpoint_)

    def start_run(self) -> None:
        """A new run begins: hit counts from zero, conditions compiled afresh against it when first met."""
        for breakpoint_ in self.by_pc.values():
            breakpoint_.hits = 0
            breakpoint_.compiled = None

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


def _key(breakpoint_: Breakpoint) -> tuple[int | None, str | None, str | None, str | None]:
    """What makes two breakpoints of a file the same one, sent again."""
    return breakpoint_.line, breakpoint_.condition, breakpoint_.hit_condition, breakpoint_.log_message


def interpolate(message: str, evaluator: Evaluator) -> str:
    """A log message with each ``{expression}`` replaced by its value (or by why it has none)."""

    def value(match: re.Match[str]) -> str:
        try:
            return shown(evaluator.evaluate(match.group(1)))
        except EvaluationError as error:
            return f"<{error}>"

    return _PLACEHOLDER.sub(value, message) + "\n"
