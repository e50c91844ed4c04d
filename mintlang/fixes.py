"""Applying the diagnostics' fixes to a text, as ``mint check --fix`` does.

A finding is fixed automatically only when it is offered exactly one fix, and
that fix is safe (``Fix.safe``) or unsafe fixes were asked for: where a finding
is offered several (respell the name, or declare it), the choice is the
author's. Fixes whose edits overlap are applied one per round, first in the
text first; the text is checked again after each round and fixed again, until
nothing more applies or ``MAX_ROUNDS`` have run (a fix that undoes another
would otherwise loop for ever).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass

from mintlang.diagnostics import Diagnostic, Edit, Fix

MAX_ROUNDS = 10


@dataclass(frozen=True, slots=True)
class Fixed:
    """A text after its fixes: what was fixed (in every round), what the final text still has."""

    text: str
    fixed: tuple[Diagnostic, ...]
    remaining: tuple[Diagnostic, ...]
    converged: bool  # False: fixes still applied after MAX_ROUNDS rounds


def automatic_fix(diagnostic: Diagnostic, *, unsafe: bool) -> Fix | None:
    """The fix ``--fix`` (with ``unsafe``: ``--unsafe-fixes``) applies to ``diagnostic``, if any."""
    if len(diagnostic.fixes) != 1:
        return None
    [fix] = diagnostic.fixes
    return fix if fix.safe or unsafe else None


def _overlaps(edit: Edit, taken: Iterable[Edit]) -> bool:
    """Two edits touch the same text, or insert at the same place (their order would be a guess)."""
    return any(
        (edit.span.start < other.span.end and other.span.start < edit.span.end) or edit.span == other.span
        for other in taken
    )


def apply_once(text: str, diagnostics: Sequence[Diagnostic], *, unsafe: bool) -> tuple[str, list[Diagnostic]]:
    """``text`` with every fix that overlaps no earlier one applied; and the diagnostics fixed."""
    taken: list[Edit] = []
    fixed: list[Diagnostic] = []
    for diagnostic in sorted(diagnostics, key=lambda d: (d.span.start, d.span.end, d.code)):
        fix = automatic_fix(diagnostic, unsafe=unsafe)
        if fix is None or any(_overlaps(edit, taken) for edit in fix.edits):
            continue
        taken.extend(fix.edits)
        fixed.append(diagnostic)
    for edit in sorted(taken, key=lambda e: e.span.start, reverse=True):
        text = text[: edit.span.start] + edit.text + text[edit.span.end :]
    return text, fixed


def fix_text(text: str, check: Callable[[str], Sequence[Diagnostic]], *, unsafe: bool) -> Fixed:
    """Fix ``text`` round after round, ``check`` finding what is left after each."""
    diagnostics = check(text)
    fixed: list[Diagnostic] = []
    for _ in range(MAX_ROUNDS):
        changed, applied = apply_once(text, diagnostics, unsafe=unsafe)
        if not applied:
            return Fixed(text, tuple(fixed), tuple(diagnostics), converged=True)
        text, diagnostics = changed, check(changed)
        fixed.extend(applied)
    still = any(automatic_fix(d, unsafe=unsafe) is not None for d in diagnostics)
    return Fixed(text, tuple(fixed), tuple(diagnostics), converged=not still)
