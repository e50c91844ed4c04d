"""What a re-run must repeat and what it must not: the editor's interventions, and the output already shown.

Stepping back re-runs the program to an earlier point from a checkpoint taken
before it (``checkpoints.py``, ``stepping.py``): the simulator is deterministic,
so that point's state is the state the first run had there, as long as the
re-run repeats what the user changed. A checkpoint taken after a point where
the user changed something, or undid a change, no longer holds the run: it is
forgotten.

- A value set while paused (``setVariable``) is an *intervention* at that point:
  each re-run applies it when it reaches the point again, before it stops there.
  Going back before it undoes it, as if it had never been made.
- What the program printed is shown once: a re-run counts its writes and
  sends on only those beyond what the console already shows. A log message
  is shown once too: only at points beyond any earlier run reached.
"""

from __future__ import annotations

from collections.abc import Callable

from mintlang.records import record
from mintlang.runtime.controller import Controller


@record
class Intervention:
    count: int  # the point it was made at
    description: str  # what it did, for the debug console
    apply: Callable[[Controller], None]


class Timeline:
    """The interventions of the session and the output shown so far."""

    def __init__(self) -> None:
        self.interventions: dict[int, list[Intervention]] = {}  # by the point they were made at
        self.writes_shown = 0  # how many of the run's writes the console shows
        self.points_reached = 0  # how many points the furthest run so far has reached

    def intervene(self, intervention: Intervention, controller: Controller) -> None:
        intervention.apply(controller)
        self.interventions.setdefault(intervention.count, []).append(intervention)

    def due(self, count: int) -> list[Intervention]:
        """The interventions to apply on reaching point ``count``, in the order they were made."""
        return self.interventions.get(count, [])

    def rewind(self, count: int) -> int | None:
        """Going back to point ``count``: interventions made after it never happened. The earliest point one is
        undone at, if any."""
        undone = [made for made in self.interventions if made > count]
        for made in undone:
            del self.interventions[made]
        return min(undone, default=None)

    def reach(self, count: int) -> None:
        self.points_reached = max(self.points_reached, count + 1)

    def first_showing(self, index: int) -> bool:
        """Whether the run's write number ``index`` is new to the console (and now shown)."""
        if index < self.writes_shown:
            return False
        self.writes_shown = index + 1
        return True
