"""The lines a rule copies with file offsets (``Context.lines``) live while that rule runs, not through
the pass: each rule asks for its own lines, and the copies of a context pass's forty rules, kept to the
last, were a run's peak memory (issue 13: 30 times the program's size at 10,000 lines). A question
that needs no node at a file offset reads the lines as parsed (``Context.placed``) and copies none."""

from __future__ import annotations

import tracemalloc
from collections.abc import Iterator

from mintlang import clear_caches
from mintlang.migrate import engine, migrate
from mintlang.migrate.context import Context
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.base import Action, Rule
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n


class _Asking(Rule):
    """Asks for every PAUSE line and keeps what it got, to compare with the next rule's."""

    rule_class = RuleClass.MECHANICAL
    phase = Phase.CONTEXT
    summary = evidence = "test"

    def __init__(self, rule_id: str, got: list[list[n.Line]]) -> None:
        self.id, self._got = rule_id, got

    def apply(self, context: Context) -> Iterator[Action]:
        self._got.append([line for _, line in context.lines(n.Pause)])
        return iter(())


def test_the_next_rule_of_a_pass_copies_the_lines_it_asks_for_afresh() -> None:
    got: list[list[n.Line]] = []
    engine.run({Unit.PROGRAM: "PAUSE IN1\nPAUSE IN2\n"}, (_Asking("T-ONE", got), _Asking("T-TWO", got)), "nextmove-pci")
    first, second = got
    assert [line.span for line in first] == [line.span for line in second]  # the same lines, file offsets
    assert not any(mine is theirs for mine, theirs in zip(first, second, strict=True))  # the first's are gone


def _loops(count: int) -> str:
    """A CANCEL, then a loop on every line: S-CANCEL asks where the lines run at power-up end (the first loop)."""
    return "CANCEL\n" + "".join(f"FOR a = 1 TO {k} : b = b + a * {k} : NEXT\n" for k in range(count))


def test_finding_where_power_up_ends_copies_no_line() -> None:
    migrate(_loops(10))  # the grammars, the keyword database and the manuals' sections: loaded once, before
    program = _loops(3000)
    clear_caches()
    tracemalloc.start()
    try:
        migrate(program)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 100 * len(program)  # 128 times when every loop line was copied and kept through the pass
