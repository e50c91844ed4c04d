"""Edits of a program's layout that must not change what it does, and runs compared across them.

Re-indenting keeps every line where it is. Inserting a blank or ``REM`` line
moves the lines after it down, so ERL, the line of the stop and the
``line N`` of every error message move with them: ``Seen.renumbered``
maps those back to the lines of the program as first written. A line the
original never had maps to a negative number, which no run shows, so a run
that points at an inserted line never compares equal.
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace

from mintlang.runtime.controller import Controller
from mintlang.runtime.observation import AxisState
from mintlang.runtime.run import run_source
from mintlang.runtime.scenario.stimulus import Scenario
from mintlang.runtime.simulation import Limits, Stop

_LINE_IN_MESSAGE = re.compile(r"\bline (\d+)\b")


@dataclass(frozen=True)
class Edited:
    """An edited source, and for each of its lines the number of that line in the original (None: inserted)."""

    source: str
    origin: tuple[int | None, ...]

    def original_line(self, line: int) -> int:
        """Where line ``line`` of the edited source was; lines past the end keep their distance from it."""
        if line < 1:
            return line
        if line > len(self.origin):
            written = [number for number in self.origin if number is not None]
            return max(written, default=0) + line - len(self.origin)
        found = self.origin[line - 1]
        return found if found is not None else -line


def reindented(source: str, indents: Sequence[str]) -> Edited:
    """Each line's indentation replaced by the next of ``indents`` (used in turn), its text otherwise unchanged."""
    lines = source.splitlines()
    indented = [indents[number % len(indents)] + line.lstrip(" \t") for number, line in enumerate(lines)]
    return Edited("".join(line + "\n" for line in indented), tuple(range(1, len(lines) + 1)))


def inserted(source: str, insertions: Mapping[int, Sequence[str]]) -> Edited:
    """``insertions[n]`` written after line ``n`` of ``source`` (0: before the first line)."""
    lines = source.splitlines()
    edited: list[str] = [*insertions.get(0, ())]
    origin: list[int | None] = [None] * len(edited)
    for number, line in enumerate(lines, start=1):
        edited.append(line)
        origin.append(number)
        after = insertions.get(number, ())
        edited.extend(after)
        origin.extend([None] * len(after))
    return Edited("".join(line + "\n" for line in edited), tuple(origin))


def gaps(source: str) -> list[int]:
    """Where a line may be inserted: before the first line and after every line but one ending in a comma.

    A trailing comma continues a DIM initialiser on the next line (000:1095-1097), so a line
    put after it would break the list in two.
    """
    lines = source.splitlines()
    return [0, *(number for number, line in enumerate(lines, start=1) if not line.rstrip().endswith(","))]


@dataclass(frozen=True)
class Seen:
    """Everything a run shows: its stop, ERR and ERL, outputs, axes, terminal, host replies and final variables."""

    stop: Stop
    err: float
    erl: float
    outputs: int
    relay: int
    axes: tuple[AxisState, ...]
    terminal: str
    host_replies: tuple[tuple[int, bytes], ...]
    variables: tuple[tuple[str, float | tuple[float, ...]], ...]

    def renumbered(self, edited: Edited) -> Seen:
        """This run of ``edited.source`` told in the line numbers of the original source."""

        def in_text(text: str) -> str:
            return _LINE_IN_MESSAGE.sub(lambda found: f"line {edited.original_line(int(found[1]))}", text)

        stop = self.stop
        line = edited.original_line(stop.line) if stop.line is not None else None
        return replace(
            self,
            stop=replace(stop, line=line, message=in_text(stop.message)),
            erl=float(edited.original_line(int(self.erl))),
            terminal=in_text(self.terminal),
        )


def seen(
    source: str,
    *,
    until_ms: int,
    every_tick: bool = False,
    config: str | None = None,
    controller: str | None = "nextmove-bx",
    dialect: str = "v4",
    scenario: Scenario | None = None,
) -> Seen:
    """Run ``source`` (after ``config``), a program in ``dialect``, until it stops or ``until_ms`` passes."""
    ran: list[Controller] = []

    def keep(controller: Controller, tick: int) -> None:
        if not ran:
            ran.append(controller)

    limits = Limits(until_ms=until_ms, max_wall_s=60.0, every_tick=every_tick)
    result = run_source(
        source, config=config, controller=controller, dialect=dialect, scenario=scenario, limits=limits, on_tick=keep
    )
    return Seen(
        result.stop,
        result.err,
        result.erl,
        result.outputs,
        result.relay,
        result.axes,
        result.terminal,
        result.host_replies,
        _variables(ran[0]) if ran else (),
    )


def _variables(controller: Controller) -> tuple[tuple[str, float | tuple[float, ...]], ...]:
    names, vm = controller.linked.names, controller.vm
    scalars = [(name, vm.scalars[slot]) for name, slot in names.scalars.items()]
    arrays = [(f"{name}()", tuple(vm.arrays[slot])) for name, slot in names.arrays.items()]
    return tuple(sorted(scalars + arrays))
