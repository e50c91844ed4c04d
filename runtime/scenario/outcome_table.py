"""The expectations of a run as a table, with what was seen and a one-line verdict (``mint-run --expect``).

Apart from ``expectations`` so that a run whose program checks nothing does not import rich.
"""

from __future__ import annotations

from collections.abc import Iterable

from rich.console import Console
from rich.table import Column, Table
from rich.text import Text

from mintlang.runtime.scenario.expectations import Outcome, stop_fails


def _expectations(count: int) -> str:
    return "1 expectation" if count == 1 else f"{count} expectations"


def render_outcomes(outcomes: Iterable[Outcome], console: Console, stopped: str | None = None) -> None:
    """A table of every expectation with what was seen, then a one-line verdict: with ``stopped``, why the run
    stopped, the verdict also says a stop no ``stopped`` expectation asks for fails the run (``stop_fails``)."""
    outcomes = tuple(outcomes)
    # The origin (file:line) is kept whole where it fits in a third of the width, ahead of the other columns,
    # which wrap at words; a longer one folds onto more lines rather than lose its line number.
    widest = max((len(str(outcome.expectation.origin)) for outcome in outcomes), default=0)
    origin = Column("expectation", overflow="fold", min_width=min(widest, console.width // 3))
    table = Table(origin, "when", "expected", "actual", "result")
    for outcome in outcomes:
        expectation = outcome.expectation
        what = Text(expectation.what)
        what.append(f"\n{expectation.origin}", style="dim")
        actual = Text(outcome.actual)
        if outcome.detail:
            actual.append(f"\n{outcome.detail}", style="dim")
        result = Text("✓", style="green") if outcome.held else Text("✗", style="bold red")
        when = "end" if expectation.at_ms is None else f"{expectation.at_ms} ms"
        table.add_row(what, when, Text(expectation.expected), actual, result)
    console.print(table)
    failed = sum(not outcome.held for outcome in outcomes)
    if failed:
        console.print(Text(f"{failed} of {_expectations(len(outcomes))} failed.", style="bold red"))
    else:
        held = "The expectation held" if len(outcomes) == 1 else f"All {len(outcomes)} expectations held"
        if stopped is not None and stop_fails(outcomes, stopped):  # else "held" over an exit status of 1
            console.print(Text(f"{held}, but the run fails: it stopped on {stopped}.", style="bold red"))
        else:
            console.print(Text(f"{held}.", style="green"))
