"""What a run must show, and whether it did.

An expectation is checked against an ``Observer``, the simulator's view of
the controller at one moment, so that this module knows nothing about how
the run is made and the simulator nothing about how expectations are written.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from enum import StrEnum
from typing import TYPE_CHECKING, Protocol

from mintlang.records import record
from mintlang.runtime.scenario.targets import Target

if TYPE_CHECKING:
    from mintlang.runtime.scenario.stimulus import Scenario

STOP_REASONS = ("end", "error", "until", "deadlock", "wall-limit")
"""Why a run stops: the program ended, an error ended it, ``--until`` ran out, W-4 deadlock, the wall-clock limit."""
NORMAL_STOPS = ("end", "until")
"""The stops of a run that went as planned; the others fail ``--expect`` unless a ``stopped`` expectation names them."""


class Comparison(StrEnum):
    """How an actual value must relate to the expected one, within the tolerance."""

    EQUAL = "="
    NOT_EQUAL = "<>"
    AT_LEAST = ">="
    AT_MOST = "<="
    ABOVE = ">"
    BELOW = "<"

    def holds(self, actual: float, expected: float, tolerance: float) -> bool:
        match self:
            case Comparison.EQUAL:
                return abs(actual - expected) <= tolerance
            case Comparison.NOT_EQUAL:
                return abs(actual - expected) > tolerance
            case Comparison.AT_LEAST:
                return actual >= expected - tolerance
            case Comparison.AT_MOST:
                return actual <= expected + tolerance
            case Comparison.ABOVE:
                return actual > expected - tolerance
            case Comparison.BELOW:
                return actual < expected + tolerance


@record
class Origin:
    """Where an expectation was written, for the report."""

    source: str
    line: int

    def __str__(self) -> str:
        return f"{self.source}:{self.line}"


def _number(value: float) -> str:
    """A value as people write it: ``1000``, ``0.5``, never ``1000.0`` or ``-0``."""
    return f"{value + 0.0:.15g}"


@record
class ValueExpectation:
    """A keyword, variable or array element compared with a number."""

    target: Target
    comparison: Comparison
    value: float
    tolerance: float
    at_ms: int | None  # None: at the end of the run
    origin: Origin

    @property
    def what(self) -> str:
        return self.target.name

    @property
    def expected(self) -> str:
        text = f"{self.comparison.value} {_number(self.value)}"
        return f"{text} ± {_number(self.tolerance)}" if self.tolerance else text


@record
class TerminalExpectation:
    """Text the program must have printed to the terminal by then: somewhere in it, or all of it (``exact``)."""

    text: str
    at_ms: int | None
    origin: Origin
    exact: bool = False

    @property
    def what(self) -> str:
        return "terminal"

    @property
    def expected(self) -> str:
        return f"is {self.text!r}" if self.exact else f"contains {self.text!r}"


@record
class StoppedExpectation:
    """Why the run must stop; known only at the end, so it has no time."""

    reason: str  # one of STOP_REASONS
    origin: Origin

    @property
    def at_ms(self) -> None:
        return None

    @property
    def what(self) -> str:
        return "stopped"

    @property
    def expected(self) -> str:
        return self.reason


Expectation = ValueExpectation | TerminalExpectation | StoppedExpectation


NO_SUCH_THING = "no such thing in this run"  # a target the run does not have: no variable, keyword or axis of it


class Observer(Protocol):
    """The simulator's view of the controller at the moment expectations are checked."""

    @property
    def terminal(self) -> str:
        """What was printed to the terminal so far, or its latest part when that is long."""
        ...

    @property
    def printed(self) -> int:
        """How many characters were printed so far, kept in ``terminal`` or not."""
        ...

    def has_printed(self, text: str) -> bool:
        """Whether ``text`` appears anywhere in what was printed so far, across lines."""
        ...

    @property
    def stopped(self) -> str:
        """Why the run stopped (one of ``STOP_REASONS``); asked only at the end."""
        ...

    @property
    def axes(self) -> tuple[int, ...]:
        """The axes of the controller, for an axis keyword written without its axis."""
        ...

    def value(self, target: str) -> float | None:
        """The value of a canonical target (``POS.0``, ``OUT``, ``COMMS(5)``, ``COUNT``); None if it has none."""
        ...

    def why_unread(self, target: str) -> str:
        """Why ``value`` gives no value for ``target``: ``NO_SUCH_THING``, or why the simulator has none to give."""
        ...


@record
class Outcome:
    """The verdict on one expectation, with what was seen, in words for the report."""

    expectation: Expectation
    held: bool
    actual: str
    detail: str  # why it failed, or ""


def evaluate(expectation: Expectation, observe: Observer) -> Outcome:
    """Check one expectation now; the simulator calls this at ``expectation.at_ms`` or at the end."""
    match expectation:
        case ValueExpectation():
            return _evaluate_value(expectation, observe)
        case TerminalExpectation(text=text, exact=True):
            return _evaluate_whole_terminal(expectation, observe)
        case TerminalExpectation(text=text):
            held = observe.has_printed(text)
            detail = "" if held else f"not among the {observe.printed} characters printed"
            return Outcome(expectation, held, _last_line(observe.terminal), detail)
        case StoppedExpectation(reason=reason):
            return Outcome(expectation, observe.stopped == reason, observe.stopped, "")


def not_reached(expectation: Expectation, stopped_ms: int) -> Outcome:
    """The verdict on a timed expectation the run stopped before: not held, since nothing was checked."""
    return Outcome(expectation, False, "not checked", f"the run stopped at {stopped_ms} ms, before this check")


def _evaluate_value(expectation: ValueExpectation, observe: Observer) -> Outcome:
    target = expectation.target
    names = [target.on_axis(axis) for axis in observe.axes] if target.every_axis else [target.text]
    if not names:
        return Outcome(expectation, False, "no axes", "the controller has no axes to check")
    readings = {name: observe.value(name) for name in names}
    missing = [name for name, value in readings.items() if value is None]
    if missing:  # named as the report names the target: a variable as the program spells it
        reasons = {(name if target.every_axis else target.name): observe.why_unread(name) for name in missing}
        if set(reasons.values()) == {NO_SUCH_THING}:
            return Outcome(expectation, False, "missing", f"{NO_SUCH_THING}: {', '.join(reasons)}")
        detail = "; ".join(why if len(reasons) == 1 else f"{name}: {why}" for name, why in reasons.items())
        return Outcome(expectation, False, "missing", detail)  # NotSimulated's message names the keyword
    values = {name: value for name, value in readings.items() if value is not None}
    failing = [
        name
        for name, value in values.items()
        if not expectation.comparison.holds(value, expectation.value, expectation.tolerance)
    ]
    if not target.every_axis:
        (actual,) = values.values()
        off = f"off by {_number(actual - expectation.value)}" if failing else ""
        return Outcome(expectation, not failing, _number(actual), off)
    if len(set(values.values())) == 1:
        shown = f"{_number(next(iter(values.values())))} on every axis"
    else:
        shown = ", ".join(f"{name} = {_number(value)}" for name, value in values.items())
    return Outcome(expectation, not failing, shown, f"fails on {', '.join(failing)}" if failing else "")


def _evaluate_whole_terminal(expectation: TerminalExpectation, observe: Observer) -> Outcome:
    """All that was printed, compared with the expected text; a failure shows where the two part."""
    printed = observe.terminal
    if observe.printed > len(printed):
        return Outcome(expectation, False, f"{observe.printed} characters", "too long to keep whole for comparison")
    if printed == expectation.text:
        return Outcome(expectation, True, f"{len(printed)} characters, the same", "")
    same = next(
        (index for index, (a, b) in enumerate(zip(printed, expectation.text, strict=False)) if a != b),
        min(len(printed), len(expectation.text)),
    )
    line = printed.count("\n", 0, same) + 1
    line_start = printed.rfind("\n", 0, same) + 1  # the two agree up to ``same``: the line starts alike
    shown_from = max(line_start, same - 20)  # the line as far as they part, but no more than 20 characters of it
    expected, actual = expectation.text[shown_from : same + 20], printed[shown_from : same + 20]
    column = same - line_start + 1
    detail = f"differs on line {line}, column {column}: expected {expected!r}, printed {actual!r}"
    return Outcome(expectation, False, f"{len(printed)} characters", detail)


def _last_line(printed: str) -> str:
    lines = [line for line in printed.splitlines() if line.strip()]
    if not lines:
        return "(nothing printed)"
    last = lines[-1] if len(lines[-1]) <= 40 else "…" + lines[-1][-39:]
    return f"last line {last!r}"


def expectations_at(scenario: Scenario) -> tuple[int, ...]:
    """The simulated times (ms) at which the run must pause and check expectations, in order."""
    return tuple(sorted({e.at_ms for e in scenario.expectations if e.at_ms is not None}))


def all_held(outcomes: Iterable[Outcome]) -> bool:
    return all(outcome.held for outcome in outcomes)


def expectations_pass(outcomes: Sequence[Outcome], stopped: str) -> bool:
    """The verdict of ``--expect``: some expectations, all held, and a normal stop unless one says how it stops.

    A run that crashed, deadlocked or ran out of wall time passes only when a
    ``stopped`` expectation asked for exactly that; no expectations is no pass.
    """
    return bool(outcomes) and all_held(outcomes) and not stop_fails(outcomes, stopped)


def stop_fails(outcomes: Sequence[Outcome], stopped: str) -> bool:
    """Whether the way the run stopped fails it whatever the other expectations say: not a normal stop, and
    no ``stopped`` expectation asked for it."""
    chosen = any(isinstance(outcome.expectation, StoppedExpectation) for outcome in outcomes)
    return not chosen and stopped not in NORMAL_STOPS
