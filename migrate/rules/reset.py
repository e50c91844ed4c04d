"""RESET: v3 cleared more state than v4 does."""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.migrate.context import MARKER, Context, FileView
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.base import Action, Rule
from mintlang.semantic.units import Unit

_OUTPUTS = frozenset({"OUT", *(f"OUT{i}" for i in range(8))})
_CLEARED = {"OUT": "OUT = 0", "TIME": "TIME = 0", "IMASK": "IMASK = <all ones>", "ENCODER": "ENCODER.<channel> = 0"}


class ResetSideEffects(Rule):
    """v3 ``RESET`` also cleared the digital outputs ("regardless of which axis is
    selected"), TIME, IMASK (255) and ENCODER among others (v3:11409, v3:11427-11444); v4 RESET
    clears the axis errors, zeroes the position and enables the drive, nothing about
    outputs (v4:15624-15629), and ENCODER is zeroed only when written (v4:9615-9623).
    Whether later code relies on the cleared state cannot be proven, and an ``OUT = 0``
    added after a v4 RESET could also switch off an output assigned with DRIVEENABLEOUTPUT,
    so nothing is written:

    * a RESET in an application that never uses OUT/OUTx, TIME, IMASK or ENCODER is equivalent;
    * so is a RESET of the configuration file that runs before any such use (the state
      is still the power-up state RESET set in v3 - the v4 guide's own port of
      INTRO.MNT keeps ``RESET`` alone, v4:144-182);
    * any other RESET is a manual item naming what v3 cleared and the application uses.
    """

    id = "S-RESET"
    rule_class = RuleClass.SEMI
    phase = Phase.CONTEXT
    summary = "RESET -> manual when the application uses OUT, TIME, IMASK or ENCODER (v3 RESET cleared them)"
    evidence = "spec S-RESET; v3:11409, v3:11427-11444; v4:15624-15629, v4:144-182"

    def apply(self, context: Context) -> Iterator[Action]:
        resets = list(context.keyword_uses("RESET"))
        if not resets:
            return  # most applications: their uses of the outputs need not be looked at
        used: dict[str, tuple[Unit, int]] = {}  # cleared keyword -> its first use in compile order
        order = {Unit.CONFIGURATION: 0, Unit.PROGRAM: 1}
        for _, use in context.keyword_uses(*_OUTPUTS, "TIME", "IMASK", "ENCODER"):
            name = "OUT" if use.keyword.keyword in _OUTPUTS else use.keyword.keyword
            place = (use.unit, use.statement.span.start)
            if name not in used or (order[place[0]], place[1]) < (order[used[name][0]], used[name][1]):
                used[name] = place
        if not used:
            return
        for file, use in resets:
            here = (order[use.unit], use.statement.span.start)
            relied = [
                name for name, (unit, start) in used.items() if (order[unit], start) < here or use.unit is Unit.PROGRAM
            ]
            if relied and not _reported(file, use.statement.span.start):
                cleared = " : ".join(_CLEARED[name] for name in _CLEARED if name in relied)
                reason = f"v3 RESET also did {cleared}; v4 RESET does not: add what later code relies on"
                yield self.flag(file, use.statement.span, reason)


def _reported(file: FileView, offset: int) -> bool:
    """Whether the RESET already has this rule's item (what v3 sees used changes as rules rewrite)."""
    for above in file.lines_above(offset):
        if not above.upper().startswith(MARKER):
            return False
        if above.startswith(f"{MARKER} {ResetSideEffects.id}:"):
            return True
    return False
