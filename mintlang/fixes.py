"""Applying the diagnostics' fixes to a text, as ``mint check --fix`` does.

A finding is fixed automatically only when it is offered exactly one fix, and
that fix is safe (``Fix.safe``) or unsafe fixes were asked for: where a finding
is offered several (respell the name, or declare it), the choice is the
author's. Fixes whose edits overlap are applied one per round, first in the
text first; the text is checked again after each round and fixed again, until
nothing more applies or ``MAX_ROUNDS`` have run (a fix that undoes another
would otherwise loop for ever). A round after which a fixed finding is still
there (the same code and message as often as before, up to where the last one
fixed was) is undone and tried again
without that fix: a declaration that cannot declare its name is not written at
all, rather than once a round. So is a round after which a line has more syntax
errors than before, as ruff reverts a fix that introduces one (a syntax error the
round mends elsewhere does not make up for it): it is tried again without the
fixes that add one on their own (all of the round's when only together they do),
so a guess never leaves the program unreadable to the compiler.
A finding like a fixed one but further on is not the fixed one left in place: the
round revealed it (the second &HFF of a line the parse reaches once the first is
mended; the line after an END SUB made RETURN, unreachable too). One that starts
before it is taken for it, and may still be a new one (the GOTO before the line
removed, unreachable once END SUB is RETURN): once the text has moved on without
them, the fixes set aside are tried again.

What the rounds leave out is kept with why (``Fixed.left_out``), and ``left_out``
finds it for a text before any fixing, as the first round would: a count of what
``--fix`` would fix counts only what it applies, and says why it leaves the rest.
"""

from __future__ import annotations

from bisect import bisect_right
from collections import Counter
from collections.abc import Callable, Collection, Iterable, Mapping, Sequence

from mintlang.codes import SYNTAX_ERRORS
from mintlang.diagnostics import Diagnostic, Edit, Fix, LineIndex, with_edits
from mintlang.records import record

MAX_ROUNDS = 10
ADDS_SYNTAX_ERROR = "the fix would add a syntax error"
STAYS = "the finding stays after the fix"


@record
class Fixed:
    """A text after its fixes: what was fixed (in every round), what the final text still has."""

    text: str
    fixed: tuple[Diagnostic, ...]
    remaining: tuple[Diagnostic, ...]
    converged: bool  # False: fixes still applied after MAX_ROUNDS rounds
    left_out: tuple[tuple[_Key, str], ...] = ()  # the findings whose fix the rounds set aside for good, and why


def automatic_fix(diagnostic: Diagnostic, *, unsafe: bool) -> Fix | None:
    """The fix ``--fix`` (with ``unsafe``: ``--unsafe-fixes``) applies to ``diagnostic``, if any."""
    if len(diagnostic.fixes) != 1:
        return None
    [fix] = diagnostic.fixes
    return fix if fix.safe or unsafe else None


def _overlaps(edit: Edit, taken: Iterable[Edit]) -> bool:
    """Two edits change the same text, or make the same insertion (two findings with one fix: one is enough).

    Different insertions at one place are made in the order of their findings (a DIM for each
    undeclared name, with the file's other DIMs).
    """
    return any(
        (edit.span.start < other.span.end and other.span.start < edit.span.end)
        or (edit.span == other.span and edit.text == other.text)
        for other in taken
    )


_Key = tuple[str, str]  # a finding's code and message: what it is, wherever it moved


def _key(diagnostic: Diagnostic) -> _Key:
    return diagnostic.code, diagnostic.message


def why_left_out(reasons: Mapping[_Key, str], diagnostic: Diagnostic) -> str | None:
    """Why the rounds set ``diagnostic``'s fix aside (``reasons``: ``left_out``'s), if they did."""
    return reasons.get(_key(diagnostic))


def apply_once(
    text: str, diagnostics: Sequence[Diagnostic], *, unsafe: bool, failed: Collection[_Key] = ()
) -> tuple[str, list[Diagnostic]]:
    """``text`` with every fix that overlaps no earlier one applied (none of a ``failed`` finding's)."""
    taken: list[Edit] = []
    fixed: list[Diagnostic] = []
    for diagnostic in sorted(diagnostics, key=lambda d: (d.span.start, d.span.end, d.code)):
        fix = automatic_fix(diagnostic, unsafe=unsafe)
        if fix is None or _key(diagnostic) in failed or any(_overlaps(edit, taken) for edit in fix.edits):
            continue
        taken.extend(fix.edits)
        fixed.append(diagnostic)
    return with_edits(text, taken), fixed


def fix_text(text: str, check: Callable[[str], Sequence[Diagnostic]], *, unsafe: bool) -> Fixed:
    """Fix ``text`` round after round, ``check`` finding what is left after each."""
    diagnostics = check(text)
    fixed: list[Diagnostic] = []
    failed: dict[_Key, str] = {}  # each finding set aside, with why
    failed_on = text  # the text the fixes in ``failed`` were set aside on
    for _ in range(MAX_ROUNDS):
        changed, applied = apply_once(text, diagnostics, unsafe=unsafe, failed=failed)
        if not applied and failed and failed_on != text:  # the text has moved on: they may fix what is left now
            failed = {}
            changed, applied = apply_once(text, diagnostics, unsafe=unsafe)
        if not applied:
            return Fixed(text, tuple(fixed), tuple(diagnostics), converged=True, left_out=tuple(failed.items()))
        found = check(changed)
        if undone := _undone(text, diagnostics, applied, found, check):
            failed |= undone  # undo the round; try it again without them
            failed_on = text
            continue
        text, diagnostics = changed, found
        fixed.extend(applied)
    still = any(automatic_fix(d, unsafe=unsafe) is not None and _key(d) not in failed for d in diagnostics)
    return Fixed(text, tuple(fixed), tuple(diagnostics), converged=not still, left_out=tuple(failed.items()))


def left_out(
    text: str,
    diagnostics: Sequence[Diagnostic],
    check: Callable[[str], Sequence[Diagnostic]],
    known: Mapping[_Key, str] | None = None,
) -> dict[_Key, str]:
    """``known`` (the findings set aside already, with why), and the findings of ``text`` (``check`` found
    ``diagnostics``) whose fix ``--fix --unsafe-fixes`` sets aside in its first round, each with why: what a
    count of the fixable findings leaves out. No check is made when every fix is known set aside."""
    known = dict(known or {})
    changed, applied = apply_once(text, diagnostics, unsafe=True, failed=known)
    return known | _undone(text, diagnostics, applied, check(changed), check) if applied else known


def _undone(
    text: str,
    before: Sequence[Diagnostic],
    applied: Sequence[Diagnostic],
    after: Sequence[Diagnostic],
    check: Callable[[str], Sequence[Diagnostic]],
) -> dict[_Key, str]:
    """The findings whose fix a round that applied ``applied`` to ``text`` must set aside, each with why: the
    finding is still there after it (``after``), or, none being so, the round added a syntax error to a line."""
    if stays := _not_fixed(before, applied, after):
        return dict.fromkeys(stays, STAYS)
    return dict.fromkeys(_breaking(text, before, applied, after, check), ADDS_SYNTAX_ERROR)


def _not_fixed(before: Sequence[Diagnostic], applied: Sequence[Diagnostic], after: Sequence[Diagnostic]) -> set[_Key]:
    """The findings whose fix left them as often as they were, less those fixed, counted up to the end of the last
    fixed finding like them: one found past it is a new one the round revealed (the parse reaches the second
    ``&HFF`` of a line once the first is mended), not one left where it was."""
    edits = _fix_edits(applied)
    reach: dict[_Key, int] = {}  # per kind, the end of the last finding fixed
    for finding in applied:
        reach[_key(finding)] = max(reach.get(_key(finding), 0), finding.span.end)
    expected = Counter(_key(finding) for finding in before if finding.span.start <= reach.get(_key(finding), -1))
    expected.subtract(map(_key, applied))
    carried = {key: _carried(end, edits) for key, end in reach.items()}
    found = Counter(_key(finding) for finding in after if finding.span.start <= carried.get(_key(finding), -1))
    return {key for key in reach if found[key] > expected[key]}


def _fix_edits(applied: Iterable[Diagnostic]) -> list[Edit]:
    """The edits of the fixes applied, each finding's one (``automatic_fix``'s)."""
    return [edit for finding in applied for edit in finding.fixes[0].edits]


def _carried(offset: int, edits: Iterable[Edit]) -> int:
    """Where ``offset`` of a text is once ``edits`` (which do not overlap) are made: moved by those before it."""
    return offset + sum(len(edit.text) - (edit.span.end - edit.span.start) for edit in edits if edit.span.end <= offset)


def _rising(
    text: str, before: Sequence[Diagnostic], applied: Sequence[Diagnostic], after: Sequence[Diagnostic]
) -> set[int]:
    """The lines of ``text`` (from 1) with more syntax errors once ``applied``'s fixes are made (``after``) than
    before: a line's own count, so that a syntax error a fix mends elsewhere does not hide one another adds."""
    index = LineIndex(text)
    origin = _origins(sorted(_fix_edits(applied), key=_start))

    def lines(found: Iterable[Diagnostic], where: Callable[[int], int]) -> Counter[int]:
        return Counter(index.position(where(d.span.start)).line for d in found if d.mint_error in SYNTAX_ERRORS)

    was = lines(before, lambda offset: offset)
    return {line for line, count in lines(after, origin).items() if count > was[line]}


def _start(edit: Edit) -> int:
    return edit.span.start


def _origins(edits: Sequence[Edit]) -> Callable[[int], int]:
    """Where an offset of the text ``edits`` (in order, not overlapping) made was before them; a place in an
    edit's new text was where that edit starts."""
    starts: list[int] = []  # where each edit's new text starts in the new text
    shifts: list[int] = []  # how far the text after each edit moved
    shift = 0
    for edit in edits:
        starts.append(edit.span.start + shift)
        shift += len(edit.text) - (edit.span.end - edit.span.start)
        shifts.append(shift)

    def origin(offset: int) -> int:
        at = bisect_right(starts, offset) - 1
        if at < 0:
            return offset
        if offset < starts[at] + len(edits[at].text):
            return edits[at].span.start
        return offset - shifts[at]

    return origin


def _lines_changed(index: LineIndex, finding: Diagnostic) -> set[int]:
    """The lines (from 1) where the edits of ``finding``'s fix start or end."""
    return {index.position(at).line for edit in finding.fixes[0].edits for at in (edit.span.start, edit.span.end)}


def _breaking(
    text: str,
    before: Sequence[Diagnostic],
    applied: Sequence[Diagnostic],
    after: Sequence[Diagnostic],
    check: Callable[[str], Sequence[Diagnostic]],
) -> set[_Key]:
    """The applied findings whose fix adds a syntax error to a line of ``text`` (the round's check found
    ``after``); every one of them when none does alone. A line that has more, changed by one fix only, names
    it without another check; otherwise the fixes are halved: a group's fixes are made together and a group
    that adds none is cleared, so one bad fix among a thousand costs some twenty checks, not a thousand."""
    rising = _rising(text, before, applied, after)
    if not rising:
        return set()
    index = LineIndex(text)
    named = [(finding, lines) for finding in applied if (lines := rising & _lines_changed(index, finding))]
    fixes_on = Counter(line for _, lines in named for line in lines)
    if all(fixes_on[line] == 1 for line in rising):
        return {_key(finding) for finding, _ in named}

    def adds(group: Sequence[Diagnostic]) -> bool:
        return bool(_rising(text, before, group, check(with_edits(text, _fix_edits(group)))))

    def culprits(group: Sequence[Diagnostic]) -> list[Diagnostic]:
        """Those of ``group``, whose fixes together add a syntax error, whose fix adds one alone."""
        if len(group) == 1:
            return list(group)
        halves = (group[: len(group) // 2], group[len(group) // 2 :])
        return [found for half in halves if adds(half) for found in culprits(half)]

    return set(map(_key, culprits(applied))) or set(map(_key, applied))
