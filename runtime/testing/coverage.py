"""Coverage of Mint programs: which lines ran, which way each branch went, which event handlers ran.

A branch is a statement with two outcomes (``mint test --coverage``): an ``IF``
(its block or line taken or not), a ``WHILE`` or ``FOR`` (its body entered or
skipped), an ``UNTIL`` (the loop left or repeated) and a ``PAUSE`` (passed at
once or waited). Each operation of the compiled program is wrapped to count
how often it ran (completed, failed into ``ERR``: the line that raised an
error ran, or blocked: a PAUSE the run stopped in was reached, and waited)
and where control went next; a run without coverage runs the operations
unwrapped.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from dataclasses import field
from pathlib import Path

from mintlang.dialect import Dialect
from mintlang.records import record
from mintlang.runtime.controller import Controller
from mintlang.runtime.errors import MintError
from mintlang.semantic.events import event_of

# Each branching statement (by syntax node) with its two outcomes: control goes on to the next operation
# (the first) or elsewhere (the second); for PAUSE, it did not wait or it waited.
OUTCOMES: Mapping[str, tuple[str, str]] = {
    "IfDo": ("taken", "not taken"),
    "IfThen": ("taken", "not taken"),
    "While": ("entered", "skipped"),
    "For": ("entered", "skipped"),
    "Until": ("left", "repeated"),
    "Pause": ("at once", "waited"),
}


@record
class Branch:
    line: int
    kind: str  # IfDo, While …
    taken: tuple[int, int]  # how often each of ``OUTCOMES[kind]`` happened

    @property
    def outcomes(self) -> tuple[str, str]:
        return OUTCOMES[self.kind]


@record
class FileCoverage:
    """One file's coverage, summed over the runs that used it."""

    path: str
    lines: Mapping[int, int]  # each line holding a statement -> how often it ran (its busiest statement's count)
    branches: tuple[Branch, ...]  # in program order
    handlers: Mapping[str, tuple[int, int]] = field(default_factory=dict)  # event handler -> (line, times run)

    def merged(self, other: FileCoverage) -> FileCoverage:
        lines = dict(self.lines)
        for line, count in other.lines.items():
            lines[line] = lines.get(line, 0) + count
        if len(self.branches) == len(other.branches):
            branches = tuple(
                Branch(mine.line, mine.kind, (mine.taken[0] + theirs.taken[0], mine.taken[1] + theirs.taken[1]))
                for mine, theirs in zip(self.branches, other.branches, strict=True)
            )
        else:  # the file changed between two runs: keep the later view
            branches = other.branches
        handlers = dict(self.handlers)
        for name, (line, count) in other.handlers.items():
            handlers[name] = (line, handlers.get(name, (line, 0))[1] + count)
        return FileCoverage(self.path, lines, branches, handlers)


class Recorder:
    """Counts, for one run, each operation's completions and outcomes (``attach`` is ``run_source``'s on_start)."""

    def __init__(self, files: Mapping[str, Path], dialect: Dialect) -> None:
        self.files = files  # "program" / "configuration" -> the file
        self.dialect = dialect  # which labels are event handlers
        self.controller: Controller | None = None
        self.ran: list[int] = []  # per operation: how often it completed, failed or began to wait
        self.outcomes: list[list[int]] = []
        self.waiting = bytearray()  # per operation: blocked, and already counted as run (and as having waited)

    def attach(self, controller: Controller) -> None:
        self.controller = controller
        vm = controller.vm
        size = len(vm.operations)
        self.ran = [0] * size
        self.outcomes = [[0, 0] for _ in range(size)]
        self.waiting = bytearray(size)
        pairs = enumerate(zip(vm.operations, vm.sites, strict=True))
        vm.operations[:] = [self._counting(pc, operation, site.kind == "Pause") for pc, (operation, site) in pairs]
        vm.fail = self._counting_failures(vm.fail)

    def _counting_failures(self, fail: Callable[[MintError, int], None]) -> Callable[[MintError, int], None]:
        """The VM's ``fail``, counting the failed statement as run: it is called once per failure, where the
        operation itself may be tried again after failing (a pure statement run ahead of its tick). A statement
        that fails after waiting was counted when it began to wait."""
        ran, waiting = self.ran, self.waiting

        def counted(error: MintError, pc: int) -> None:
            if waiting[pc]:
                waiting[pc] = 0
            else:
                ran[pc] += 1
            fail(error, pc)

        return counted

    def _counting(self, pc: int, operation: Callable[[], bool | None], pausing: bool) -> Callable[[], bool]:
        vm = self.controller.vm  # type: ignore[union-attr]
        ran, outcome, waiting = self.ran, self.outcomes[pc], self.waiting

        def counted() -> bool:
            if operation():
                # counted as it begins to wait: the run may stop before it completes (at the last timed check,
                # or an event handler's END), and the program was there all the same
                if not waiting[pc]:
                    waiting[pc] = 1
                    ran[pc] += 1
                    if pausing:
                        outcome[1] += 1
                return True
            if waiting[pc]:
                waiting[pc] = 0
            else:
                ran[pc] += 1
                if pausing:
                    outcome[0] += 1
            if not pausing:
                outcome[0 if vm.pc == pc + 1 else 1] += 1
            return False

        return counted

    def result(self) -> tuple[FileCoverage, ...]:
        controller = self.controller
        if controller is None:  # the program never started
            return ()
        sites = controller.vm.sites
        ran = self._ran_as_written(controller)
        found = []
        for unit, path in self.files.items():
            pcs = [pc for pc, site in enumerate(sites) if site.unit == unit and not site.declares]
            lines: dict[int, int] = {}
            for pc in pcs:
                lines[sites[pc].line] = max(lines.get(sites[pc].line, 0), ran[pc])
            branches = tuple(
                Branch(sites[pc].line, sites[pc].kind, (self.outcomes[pc][0], self.outcomes[pc][1]))
                for pc in pcs
                if sites[pc].kind in OUTCOMES
            )
            handlers = self._handlers(unit, controller)
            found.append(FileCoverage(str(path), lines, branches, handlers))
        return tuple(found)

    def _ran_as_written(self, controller: Controller) -> list[int]:
        """How often each operation ran as a reader of the program counts it: an ELSE runs as the jump that
        ends the true branch, but its line is the start of the false branch and the block ends at ENDIF."""
        ran = list(self.ran)
        for middle, (opener, closer) in controller.linked.elses.items():
            ran[closer] += self.ran[middle]  # each true branch ended at the ENDIF it jumped past
            ran[middle] = self.outcomes[opener][1]  # each time the IF was not taken, the ELSE branch began
        return ran

    def _handlers(self, unit: str, controller: Controller) -> dict[str, tuple[int, int]]:
        linked = controller.linked
        labels = linked.handlers if unit == "program" else linked.configuration_handlers
        sites = controller.vm.sites
        return {
            name: (sites[pc].line, self.ran[pc])
            for name, pc in labels.items()
            if event_of(name, self.dialect) is not None and pc < len(sites)
        }


def merge(runs: Iterable[tuple[FileCoverage, ...]]) -> list[FileCoverage]:
    """Every file's coverage over all runs, by path, in the order first met."""
    by_path: dict[str, FileCoverage] = {}
    for run in runs:
        for file in run:
            known = by_path.get(file.path)
            by_path[file.path] = file if known is None else known.merged(file)
    return list(by_path.values())


def lcov(files: Iterable[FileCoverage]) -> str:
    """The lcov tracefile of ``files``: lines (DA), branches (BRDA, one block per branch statement) and the
    event handlers as functions (FN, FNDA), which editors' coverage views and genhtml read."""
    records = []
    for file in files:
        record = ["TN:", f"SF:{file.path}"]
        for name, (line, _) in sorted(file.handlers.items(), key=lambda item: item[1][0]):
            record.append(f"FN:{line},#{name}")
        for name, (_, count) in sorted(file.handlers.items(), key=lambda item: item[1][0]):
            record.append(f"FNDA:{count},#{name}")
        record += [f"FNF:{len(file.handlers)}", f"FNH:{handlers_run(file)}"]
        for block, branch in enumerate(file.branches):
            record += [f"BRDA:{branch.line},{block},{side},{count}" for side, count in enumerate(branch.taken)]
        record += [f"BRF:{2 * len(file.branches)}", f"BRH:{outcomes_seen(file)}"]
        record += [f"DA:{line},{count}" for line, count in sorted(file.lines.items())]
        record += [f"LF:{len(file.lines)}", f"LH:{lines_run(file)}", "end_of_record"]
        records.append("\n".join(record))
    return "\n".join(records) + "\n" if records else ""


def lines_run(file: FileCoverage) -> int:
    return sum(1 for count in file.lines.values() if count)


def outcomes_seen(file: FileCoverage) -> int:
    return sum(1 for branch in file.branches for count in branch.taken if count)


def handlers_run(file: FileCoverage) -> int:
    return sum(1 for _, count in file.handlers.values() if count)
