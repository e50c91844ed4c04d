"""TRON and TROFF: the program trace, each line's number printed as the line runs (000:16912-16947).

The guide's description: every line executed prints its number in square brackets, ``C`` for the
configuration file and ``P`` for the program, and both keywords work inside a program. Its example
prints the marks one after the other, a space after each, among what the program prints:
``[P 1] [P 2] [P 3] 1``. A line runs again when control comes back to it, from a loop (``[P 4] [P 3]``
each pass), a handler's RETURN, or a jump back within it; a statement blocked and tried again on a
later tick (``PAUSE``, ``WAIT``) is still the same execution and prints nothing more. ``TRON``'s own
line shows, as the example's ``[P 1]`` does.

While the trace is on every operation is wrapped (as the debugger and coverage wrap them) and none
counts as pure, so the marks come out in the order and at the ticks the lines run; ``TROFF`` puts the
operations back as they were.
"""

from __future__ import annotations

from mintlang.runtime.interpreter.vm import Interpreter, Operation, Site
from mintlang.runtime.keywords import Channels, KeywordTable
from mintlang.runtime.terminal import Terminal


def mark(site: Site) -> str:
    """``[P 12] ``: the line's file (``C`` configuration, ``P`` program) and number, then the separator."""
    return f"[{'C' if site.unit == 'configuration' else 'P'} {site.line}] "


class LineTrace:
    def __init__(self, vm: Interpreter, terminal: Terminal) -> None:
        self.vm = vm
        self.terminal = terminal
        self._untraced: tuple[list[Operation], bytes] | None = None  # the operations and purity before TRON
        self._line: tuple[str, int] | None = None  # the line the last statement run is on
        self._last_pc = -1
        self._blocked_pc: int | None = None  # the statement that blocked last: tried again, it is no new run

    def register(self, table: KeywordTable) -> None:
        table.register("TRON", command=self._on)
        table.register("TROFF", command=self._off)

    def _on(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        vm = self.vm
        if self._untraced is not None:
            return False
        self._untraced = (list(vm.operations), bytes(vm.pure))
        vm.operations[:] = [self._traced(pc, operation) for pc, operation in enumerate(vm.operations)]
        vm.pure[:] = bytes(len(vm.pure))
        pc = vm.executing
        if pc is not None:  # TRON's own line is running with the trace on
            site = vm.sites[pc]
            self.terminal.write(mark(site))
            self._line, self._last_pc, self._blocked_pc = (site.unit, site.line), pc, None
        return False

    def _off(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        if self._untraced is not None:
            operations, pure = self._untraced
            self.vm.operations[:] = operations
            self.vm.pure[:] = pure
            self._untraced = None
        return False

    def _traced(self, pc: int, operation: Operation) -> Operation:
        site = self.vm.sites[pc]
        line = (site.unit, site.line)
        text = mark(site)
        write = self.terminal.write

        def traced() -> bool | None:
            if self._blocked_pc != pc and (line != self._line or pc <= self._last_pc):
                write(text)
            self._line, self._last_pc, self._blocked_pc = line, pc, None
            blocked = operation()
            if blocked:
                self._blocked_pc = pc
            return blocked

        return traced
