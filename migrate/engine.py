"""Running the rules: phases in the spec's order, non-overlapping span edits, a fixed point.

Each phase re-parses the current text, asks its rules for actions, applies the
edits that do not overlap an earlier rule's edit (the rest wait for the next
pass of the same phase, on the re-parsed text) and repeats until the phase has
nothing left to do. Flags become ``REM MIGRATE:`` lines above the flagged line,
with its indentation and the file's own newline (a statement after the AUTO or
PROTECT that must open its file first gets a line of its own); a marker already
there is not written twice, which is what makes a second migration a no-op.

Text outside the edited spans is copied, never regenerated: comments, spacing,
case, blank lines, CRLF and characters of any code page survive as they were.
"""

from __future__ import annotations

from bisect import bisect_left, bisect_right, insort
from collections import Counter
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

from mintlang.allocation import without_collector
from mintlang.diagnostics import LineIndex, Severity, Span, split_lines
from mintlang.migrate.context import MARKER, MARKER_LINE, Context, FileView
from mintlang.migrate.model import Change, ManualItem, Phase
from mintlang.migrate.rules.base import Flag, Replace, Rule
from mintlang.semantic.units import Unit

MAX_PASSES = 6  # a phase that still edits after this many passes has a rule that is not idempotent


@dataclass(frozen=True, slots=True)
class _Edit:
    rule: str
    span: Span
    text: str


@dataclass(frozen=True, slots=True)
class _Batch:
    """The edits of one pass, sorted, with where each ends in the text they produced and how much
    the edits before it grew the text (one more: all of them), so that mapping an offset back
    is a bisection instead of a walk over every edit."""

    edits: list[_Edit]
    new_ends: list[int]
    shifts: list[int]

    @classmethod
    def of(cls, edits: list[_Edit]) -> _Batch:
        new_ends: list[int] = []
        shifts = [0]
        for edit in edits:
            new_ends.append(edit.span.start + shifts[-1] + len(edit.text))
            shifts.append(shifts[-1] + len(edit.text) - (edit.span.end - edit.span.start))
        return cls(edits, new_ends, shifts)


@dataclass
class _FileState:
    """One file through the phases: its current text and how each pass changed it."""

    source: str
    text: str
    index: LineIndex
    batches: list[_Batch] = field(default_factory=list)  # applied edits, per pass, on the text before it
    changes: list[Change] = field(default_factory=list)
    counts: Counter[str] = field(default_factory=Counter)


@dataclass(frozen=True, slots=True)
class FileOutcome:
    source: str
    text: str
    changes: tuple[Change, ...]
    manual: tuple[ManualItem, ...]
    counts: Mapping[str, int]
    errors: tuple[str, ...]  # what the v3 parser could not read in the original


@without_collector  # the parse trees are acyclic and large: collections would walk them again and again
def run(texts: Mapping[Unit, str], rules: Sequence[Rule], controller: str) -> dict[Unit, FileOutcome]:
    """Migrate the files of one application with ``rules`` (already filtered and ordered).

    A pass that changed nothing leaves its context valid: the next phase starts from it
    instead of parsing the same text again.
    """
    states = {unit: _FileState(text, text, LineIndex(text)) for unit, text in texts.items()}
    context: Context | None = Context.build(texts, controller)
    errors = {unit: _unreadable(file) for unit, file in context.files.items()}
    for phase in Phase:
        active = [rule for rule in rules if rule.phase is phase]
        if not active:
            continue
        for _ in range(MAX_PASSES):
            if context is None:
                context = Context.build({unit: state.text for unit, state in states.items()}, controller)
            if not _apply_pass(context, active, states):
                break
            context = None  # stale: dropped before the next parse, so two trees are never alive at once
        else:  # pragma: no cover - guards against a rule that never settles
            raise RuntimeError(f"phase {phase} did not reach a fixed point")
    return {unit: _outcome(state, errors[unit]) for unit, state in states.items()}


def _unreadable(file: FileView) -> tuple[str, ...]:
    index = file.document.line_index
    return tuple(
        f"line {index.position(d.span.start).line}: {d.code} {d.message}"
        for d in file.document.diagnostics
        if d.severity is Severity.ERROR
    )


def _apply_pass(context: Context, rules: Sequence[Rule], states: dict[Unit, _FileState]) -> bool:
    wanted: dict[Unit, list[_Edit]] = {unit: [] for unit in states}
    flagged: set[tuple[Unit, int, str]] = set()
    for rule in rules:
        for action in rule.apply(context):
            file = context.files[action.unit]
            if isinstance(action, Replace):
                wanted[action.unit].append(_Edit(rule.id, action.span, action.text))
            elif isinstance(action, Flag):
                edit = _marker(file, rule.id, action, flagged)
                if edit is not None:
                    wanted[action.unit].append(edit)
    changed = False
    for unit, edits in wanted.items():
        accepted = _non_overlapping(edits)
        if accepted:
            _apply(states[unit], accepted)
            changed = True
    return changed


def _marker(file: FileView, rule: str, flag: Flag, flagged: set[tuple[Unit, int, str]]) -> _Edit | None:
    """The ``REM MIGRATE:`` line for a flag, unless that line already carries it.

    Nothing may go above the command that must open the file (AUTO, PROTECT): a flag for a
    statement after it on its line breaks the line there instead (a line end separates
    statements as ``:`` does), so the statement gets a line of its own with the marker above.
    """
    reason = " ".join(flag.reason.split())
    text = f"{MARKER} {rule}: {reason}"
    indentation = file.indentation(flag.span.start)
    split = _after_opening(file, flag.span.start)
    start = file.line_start(flag.span.start) if split is None else split.start
    key = (file.unit, start, text)
    if key in flagged:
        return None
    flagged.add(key)
    if split is not None:
        return _Edit(rule, split, f"{file.newline}{indentation}{text}{file.newline}{indentation}")
    for above in file.lines_above(flag.span.start):
        if not above.upper().startswith(MARKER):
            break
        if above == text:
            return None
    return _Edit(rule, Span(start, start), f"{indentation}{text}{file.newline}")


def _after_opening(file: FileView, offset: int) -> Span | None:
    """The separator (`` : ``) after the command that opens the file, when ``offset`` lies in a
    statement following that command on its line; None otherwise."""
    line = file.opening
    if line is None or len(line.statements) < 2:
        return None
    command, following = line.statements[:2]
    if not command.span.end <= offset < line.span.end:
        return None
    return Span(command.span.end, following.span.start)


def _non_overlapping(edits: list[_Edit]) -> list[_Edit]:
    """The edits that touch no earlier-accepted edit (rule order decides), sorted by position.

    Insertions at one point keep the order they were asked for; an insertion may
    sit at either end of a replacement, never inside it. The accepted replacements
    (which never overlap) and insertion points are kept sorted, so each check is a
    bisection, not a comparison with every edit accepted so far.
    """
    accepted: list[_Edit] = []
    replacements: list[tuple[int, int]] = []
    points: list[int] = []
    for edit in edits:
        start, end = edit.span
        before = bisect_left(replacements, (end, end)) - 1  # the last replacement starting before ``end``
        if start == end:
            if before >= 0 and replacements[before][0] < start < replacements[before][1]:
                continue
            insort(points, start)
        else:
            if before >= 0 and replacements[before][1] > start:
                continue
            inside = bisect_right(points, start)
            if inside < len(points) and points[inside] < end:
                continue
            insort(replacements, (start, end))
        accepted.append(edit)
    return sorted(accepted, key=lambda edit: (edit.span.start, edit.span.end))


def _apply(state: _FileState, edits: list[_Edit]) -> None:
    parts: list[str] = []
    position = 0
    for edit in edits:
        parts.append(state.text[position : edit.span.start])
        parts.append(edit.text)
        position = edit.span.end
        if edit.span.start != edit.span.end or not edit.text.lstrip().startswith(MARKER):  # a line split counts
            original = _to_source(state, edit.span)
            line = state.index.position(original.start).line
            state.changes.append(
                Change(edit.rule, original, line, state.source[original.start : original.end], edit.text)
            )
            state.counts[edit.rule] += 1
    parts.append(state.text[position:])
    state.batches.append(_Batch.of(edits))
    state.text = "".join(parts)


def _to_source(state: _FileState, span: Span) -> Span:
    """``span`` of the current text mapped back to the original source.

    Offsets outside earlier edits shift by those edits' growth; an offset inside
    text an earlier edit wrote maps to the whole span that edit replaced.
    """
    start, end = span
    for batch in reversed(state.batches):
        start = _back(batch, start, at_start=True)
        end = start if span.start == span.end else _back(batch, end, at_start=False)
    return Span(start, max(start, end))


def _back(batch: _Batch, offset: int, *, at_start: bool) -> int:
    first = bisect_left(batch.new_ends, offset)  # the edits before it end before ``offset``
    shift = batch.shifts[first]
    for edit in batch.edits[first:]:
        new_start = edit.span.start + shift
        new_end = new_start + len(edit.text)
        if offset < new_start or (offset == new_start and at_start and edit.span.start != edit.span.end):
            break
        if offset < new_end or (offset == new_end and not at_start and offset > new_start):
            return edit.span.start if at_start else edit.span.end
        shift += len(edit.text) - (edit.span.end - edit.span.start)
    return offset - shift


def _outcome(state: _FileState, errors: tuple[str, ...]) -> FileOutcome:
    manual = tuple(_manual_items(state.text))
    counts = Counter(state.counts)
    for item in manual:
        counts[item.rule] += 1
    return FileOutcome(state.source, state.text, tuple(state.changes), manual, dict(sorted(counts.items())), errors)


def _manual_items(text: str) -> list[ManualItem]:
    """Every ``REM MIGRATE:`` line of the text, with the line it flags (the next non-marker line)."""
    items: list[ManualItem] = []
    pending: list[tuple[str, str]] = []
    for number, line in enumerate(split_lines(text), start=1):
        found = MARKER_LINE.match(line)
        if found:
            pending.append((found["rule"], found["reason"]))
            continue
        items.extend(ManualItem(rule, number, reason) for rule, reason in pending)
        pending = []
    return items
