"""Running the rules: phases in the spec's order, non-overlapping span edits, a fixed point.

Each phase re-parses the current text, asks its rules for actions, applies the
edits that do not overlap an earlier rule's edit (the rest wait for the next
pass of the same phase, on the re-parsed text) and repeats until the phase has
nothing left to do but write the marker lines it asked for; a phase in
``SETTLED_IN_ONE_PASS`` is done after a pass whose edits all applied.
Flags become ``REM MIGRATE:`` lines above the flagged line,
with its indentation and the file's own newline (a statement after the AUTO or
PROTECT that must open its file first gets a line of its own, and the AUTO or PROTECT
line a marker below it that says so: ``marks_above``); a marker already
there is not written twice, which is what makes a second migration a no-op.

Text outside the edited spans is copied, never regenerated: comments, spacing,
case, blank lines, CRLF and characters of any code page survive as they were.

A rule that raises, or a phase still editing after ``MAX_PASSES`` passes (a rule
rewriting its own output), raises ``MigrationFailed`` naming the rule, so the
caller can report it and go on with other files. ``history`` maps every change
and marked line back to the original and forward to the migrated text.
"""

from __future__ import annotations

from bisect import bisect_left, bisect_right, insort
from collections import Counter
from collections.abc import Callable, Mapping, Sequence
from dataclasses import field, replace
from functools import partial

from mintlang.allocation import kept_without_collector
from mintlang.caching import Shelf, apart, forget_lines, keeping_what_it_uses
from mintlang.diagnostics import LineIndex, Span, split_lines
from mintlang.migrate.citations import cite, in_file
from mintlang.migrate.context import (
    MARKER,
    Context,
    FileView,
    LineTags,
    Unreadable,
    marker_insertion,
    marker_text,
    marks_line_above,
)
from mintlang.migrate.history import Edit, History
from mintlang.migrate.markers import manual_items
from mintlang.migrate.model import Change, ManualItem, MigrationFailed, Phase, unreadable
from mintlang.migrate.rules.base import Flag, Replace, Rule
from mintlang.migrate.rules.manual import v3_errors
from mintlang.records import record
from mintlang.semantic.units import Unit
from mintlang.syntax.parser import Document
from mintlang.syntax.reread import Replaced

MAX_PASSES = 6  # a phase that still edits after this many passes has a rule that is not idempotent

# Phases whose rules, once every edit they asked for is applied, ask for nothing on the text they
# wrote: each rewrites a word into one that none of them rewrites (a full v3 name, a v4 name, a
# user name no keyword has), or inserts what it finds missing (a DIM, AXES, the input edge modes,
# the default master, the v3 defaults, an axis list), which is what it and the others look for to
# find it missing. The pass confirming it read the text again and re-ran every rule to find nothing
# (M-DIM on a semantic model of its own); it is skipped, so a rule of these phases rewriting its own
# output would go unseen at run time: tests/migrate/test_phases_settle_in_one_pass.py runs that pass on the
# corpora (with the optional rules too) and on every keyword of both dialects and holds it to
# finding nothing. The other phases keep their confirming pass: their rules may feed one another
# (S-ACCEL copies a value M-PREC then brackets).
SETTLED_IN_ONE_PASS = frozenset({Phase.ABBREVIATIONS, Phase.RENAMES, Phase.INSERTIONS})

# The last phase: its rule (X-CHECK) reads the result as Mint v4 and asks for no line's tags, and no
# Mint v3 reading follows it that the run's per-line caches would spare work (a second pass, which
# only a line split at an opening AUTO or PROTECT could bring, reads afresh). What they held was
# alive beside the Mint v4 reading, the peak of a run: the tags about 3 times the program's size.
_LAST = Phase.CHECK


@record
class _Applied:
    """A change before the migrated text is known: the pass that made it and where its
    replacement starts in the text that pass produced."""

    change: Change
    after: int
    offset: int


@record(frozen=False, slots=False)
class _FileState:
    """One file through the phases: its current text and how each pass changed it."""

    source: str
    text: str
    index: LineIndex
    history: History = field(default_factory=History)
    applied: list[_Applied] = field(default_factory=list)
    counts: Counter[str] = field(default_factory=Counter)
    # The reading of the text before the last pass's edits, and those edits (``Replaced``): what the
    # next context takes over of it (``Context.reading``); None once read, or where there is none.
    read: Document | None = None
    since: list[Replaced] = field(default_factory=list)


@record
class FileOutcome:
    source: str
    text: str
    changes: tuple[Change, ...]
    manual: tuple[ManualItem, ...]
    counts: Mapping[str, int]
    errors: tuple[str, ...]  # what the original's reader (v3; v4 to MintMT) could not read


@kept_without_collector  # acyclic and large: collections would walk the trees and the caches they fill
def run(texts: Mapping[Unit, str], rules: Sequence[Rule], controller: str) -> dict[Unit, FileOutcome]:
    """Migrate the files of one application with ``rules`` (already filtered and ordered).

    A pass that changed nothing leaves its context valid: the next phase starts from it
    instead of parsing the same text again. The tags of the lines last read are kept for the
    next pass: most lines come through a pass unchanged. The per-line caches are the run's own (``apart``), and
    after each re-read they keep only what it used, and what they hold about its unchanged lines
    (``keeping_what_it_uses``): the versions of lines the passes replaced piled up to a fifth of a run's memory,
    and each model and check walked every line again. The run's Mint v4 readings
    (X-COMMENTED's, when a line is in error in v3, then X-CHECK's of that text with its markers)
    share theirs (``Shelf``), kept apart from the v3 ones.
    """
    with apart():
        return _run(texts, rules, controller)


def _run(texts: Mapping[Unit, str], rules: Sequence[Rule], controller: str) -> dict[Unit, FileOutcome]:
    states = {unit: _FileState(text, text, LineIndex(text)) for unit, text in texts.items()}
    tags, v4_shelf = LineTags(), Shelf()
    context: Context | None = _build(texts, controller, tags, v4_shelf)
    errors = _unreadable(context)
    for phase in Phase:
        active = [rule for rule in rules if rule.phase is phase]
        if not active:
            continue
        editing: set[str] = set()
        for _ in range(MAX_PASSES):
            if context is None:
                reading = partial(_reread, states, controller, tags, v4_shelf)
                context = keeping_what_it_uses(reading, Context.lines_read)
            if phase is _LAST:
                tags.clear()
                forget_lines()
            wanted = _asked(context, active, states)
            if any(wanted.values()):
                # stale, and applying the edits needs none of it: dropped before they make a second text
                # (a run's peak was there, the model beside the old and new text), and before the next
                # parse, so two trees are never alive at once; its readings are kept, which the lines no
                # edit touches are taken over from (the trees of those lines are the next reading's)
                _keep_readings(context, states)
                context = None
            editing, settled = _apply_pass(wanted, states, one_pass=phase in SETTLED_IN_ONE_PASS)
            if settled:
                break
        else:
            reason = f"it kept rewriting its own output ({MAX_PASSES} passes of the {phase} phase)"
            raise MigrationFailed(", ".join(sorted(editing)), reason)
        if context is not None:  # the next phase starts from it: not with the lines this one copied
            context.forget_copies()
    v4_shelf.clear()  # the last Mint v4 reading is done: its lines were a third of the peak after it
    return {unit: _outcome(state, errors[unit]) for unit, state in states.items()}


def _build(texts: Mapping[Unit, str], controller: str, tags: LineTags, v4_shelf: Shelf) -> Context:
    return _read_or_fail(partial(Context.build, texts, controller, tags, v4_shelf))


def _reread(states: Mapping[Unit, _FileState], controller: str, tags: LineTags, v4_shelf: Shelf) -> Context:
    """The context of the files' current texts, from the readings ``_keep_readings`` kept, which it lets go."""
    texts = {unit: state.text for unit, state in states.items()}
    earlier = {unit: (state.read, state.since) for unit, state in states.items() if state.read is not None}
    for state in states.values():
        state.read, state.since = None, []
    return _read_or_fail(partial(Context.reading, texts, controller, tags, v4_shelf, earlier))


def _read_or_fail(read: Callable[[], Context]) -> Context:
    try:
        return read()
    except Exception as error:  # a parser bug must not take the other files of a run with it
        raise _unreadable_files(error) from error


def _keep_readings(context: Context, states: Mapping[Unit, _FileState]) -> None:
    """Keep each file's reading in ``context`` for the next one, with none of the lines it copied with
    file offsets (``Document.lines``, when something asked for them)."""
    for unit, file in context.files.items():
        file.document.__dict__.pop("lines", None)
        states[unit].read, states[unit].since = file.document, []


def _unreadable_files(error: BaseException | None) -> MigrationFailed:
    return MigrationFailed(None, f"reading it as Mint v3 raised {_described(error)}")


def _described(error: BaseException | None) -> str:
    return f"{type(error).__name__}: {error}"


def _unreadable(context: Context) -> dict[Unit, tuple[str, ...]]:
    """The errors ``mint check --dialect v3`` finds in each original file, as X-COMMENTED reads them: the lines
    the report calls unreadable are the lines it says are not valid Mint v3 (``MOVEA =``, which the grammar
    reads and the check finds no value in, as well as a character no v3 line has)."""
    try:
        found = v3_errors(context)
    except Unreadable as error:  # the model, built for the check
        raise _unreadable_files(error.__cause__) from error.__cause__
    return {file.unit: tuple(unreadable(file.line_number(d.span.start), d) for d in errors) for file, errors in found}


def _asked(context: Context, rules: Sequence[Rule], states: dict[Unit, _FileState]) -> dict[Unit, list[Edit]]:
    """The edits ``rules`` ask for in one pass, per file, in rule order; the lines each rule copied go with it."""
    wanted: dict[Unit, list[Edit]] = {unit: [] for unit in states}
    flagged: set[tuple[Unit, int, str]] = set()
    for rule in rules:
        try:
            for action in rule.apply(context):
                file = context.files[action.unit]
                if isinstance(action, Replace):
                    wanted[action.unit].append(Edit(rule.id, action.span, action.text))
                elif isinstance(action, Flag):
                    edit = _marker(file, rule.id, action, flagged)
                    if edit is not None:
                        wanted[action.unit].append(edit)
        except Unreadable as error:  # the model, built when the rule asked for it
            raise _unreadable_files(error.__cause__) from error.__cause__
        except Exception as error:  # a bug in one rule: reported with its id, the run goes on
            raise MigrationFailed(rule.id, _described(error)) from error
        context.forget_line_copies()
    return wanted


def _apply_pass(
    wanted: dict[Unit, list[Edit]], states: dict[Unit, _FileState], *, one_pass: bool
) -> tuple[set[str], bool]:
    """Apply the edits of one pass: the ids of the rules whose edits were applied, and whether the phase
    is done. It is when the rules asked for nothing, or for marker lines only: a comment line
    changes no syntax a rule reads, so another pass would ask for the same markers, found written;
    or, for a phase ``one_pass`` (``SETTLED_IN_ONE_PASS``), when no edit was held back by an
    overlapping one."""
    applied: set[str] = set()
    held_back = False
    for unit, edits in wanted.items():
        accepted = _non_overlapping(edits)
        held_back |= len(accepted) < len(edits)
        if accepted:
            _apply(states[unit], accepted)
            applied.update(edit.rule for edit in accepted)
    settled = one_pass and not held_back
    return applied, settled or all(_writes_markers(edit) for edits in wanted.values() for edit in edits)


def _writes_markers(edit: Edit) -> bool:
    """Whether ``edit`` inserts whole ``REM MIGRATE:`` lines and nothing else (a line split does more)."""
    lines = _inserted_lines(edit)
    return bool(lines) and all(_is_marker(line) for line in lines)


def _inserts_lines_above(edit: Edit) -> bool:
    """Whether ``edit`` inserts whole lines, none of them a marker: lines that go above the line at its point."""
    lines = _inserted_lines(edit)
    return bool(lines) and not any(_is_marker(line) for line in lines)


def _inserted_lines(edit: Edit) -> list[str]:
    """The lines ``edit`` inserts when it inserts whole lines and nothing else; none otherwise."""
    lines = split_lines(edit.text, keepends=True)
    whole = edit.span.start == edit.span.end and all(line.endswith(("\n", "\r")) for line in lines)
    return lines if whole else []


def _is_marker(line: str) -> bool:
    return line.lstrip().startswith(MARKER)


def _marker(file: FileView, rule: str, flag: Flag, flagged: set[tuple[Unit, int, str]]) -> Edit | None:
    """The ``REM MIGRATE:`` line for a flag, unless that line already carries it.

    Nothing may go above the command that must open the file (AUTO, PROTECT): a flag for that
    command gets a marker right below it that says it marks the line above (``marks_above``).
    When a statement follows the command on its line, the line is broken there instead (a line
    end separates statements as ``:`` does) and the marker goes between the two: below the
    command for a flag of the command, above the statement for a flag of the statement.
    """
    reason = in_file(cite(" ".join(flag.reason.split())))
    below = file.in_opening_command(flag.span.start)
    text = marker_text(rule, reason, above=below)
    split = file.after_opening if below else _after_opening(file, flag.span.start)
    start = file.line_start(flag.span.start) if split is None else split.start
    key = (file.unit, start, text)
    if key in flagged:
        return None
    flagged.add(key)
    if split is not None:
        indentation = file.indentation(flag.span.start)
        return Edit(rule, split, f"{file.newline}{indentation}{text}{file.newline}{indentation}")
    placed = marker_insertion(file.text, start, text, file.newline)
    return None if placed is None else Edit(rule, Span(placed[0], placed[0]), placed[1])


def _after_opening(file: FileView, offset: int) -> Span | None:
    """The separator (`` : ``) after the command that opens the file, when ``offset`` lies in a
    statement following that command on its line; None otherwise."""
    split = file.after_opening
    if split is None or not split.start <= offset < file.line_end(split.start):
        return None
    return split


def _non_overlapping(edits: list[Edit]) -> list[Edit]:
    """The edits that touch no earlier-accepted edit (rule order decides), sorted by position.

    Insertions at one point keep the order they were asked for, except that a marker of the
    line above (``marks_above``) goes first, to stay right below that line, and whole lines
    (``DIM a``) go above the rest: a marker asked for there belongs to the line below
    it, and other text inserted there begins that line. An insertion may sit at either
    end of a replacement, never inside it. The accepted replacements
    (which never overlap) and insertion points are kept sorted, so each check is a
    bisection, not a comparison with every edit accepted so far.
    """
    accepted: list[Edit] = []
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
    return sorted(accepted, key=lambda edit: (edit.span.start, edit.span.end, _rank_at_a_point(edit)))


def _rank_at_a_point(edit: Edit) -> int:
    """Where ``edit`` goes among the insertions at its point: a marker of the line above, whole lines, the rest."""
    if marks_line_above(edit.text):
        return 0
    return 1 if _inserts_lines_above(edit) else 2


def _apply(state: _FileState, edits: list[Edit]) -> None:
    parts: list[str] = []
    position = 0
    written = 0  # length of the new text so far
    passes = len(state.history.batches) + 1
    for edit in edits:
        before = state.text[position : edit.span.start]
        parts += (before, edit.text)
        written += len(before)
        position = edit.span.end
        if edit.span.start != edit.span.end or not edit.text.lstrip().startswith(MARKER):  # a line split counts
            original = state.history.to_source(edit.span)
            line = state.index.position(original.start).line
            change = Change(edit.rule, original, line, state.source[original.start : original.end], edit.text, 0)
            state.applied.append(_Applied(change, passes, written))
            state.counts[edit.rule] += 1
        written += len(edit.text)
    parts.append(state.text[position:])
    if state.since:  # a second batch since the reading: the text is read afresh
        state.read = None
    state.since = [(edit.span.start, edit.span.end, len(edit.text)) for edit in edits]
    state.history.record(edits)
    state.text = "".join(parts)


def _outcome(state: _FileState, errors: tuple[str, ...]) -> FileOutcome:
    index = LineIndex(state.text)
    changes = [
        replace(item.change, migrated_line=index.position(state.history.forward(item.offset, item.after)).line)
        for item in state.applied
    ]
    changes.sort(key=lambda change: change.span.start)  # stable: edits at one place keep their order
    manual = tuple(manual_items(state.text, state.history.origin, state.index))
    return FileOutcome(state.source, state.text, tuple(changes), manual, _counts(state.counts, manual), errors)


def untouched(text: str) -> FileOutcome:
    """``text`` left as it was: its own ``REM MIGRATE:`` lines are its manual items."""
    index = LineIndex(text)
    manual = tuple(manual_items(text, lambda offset: offset, index))
    return FileOutcome(text, text, (), manual, _counts(Counter(), manual), ())


def _counts(changes: Counter[str], manual: tuple[ManualItem, ...]) -> dict[str, int]:
    counts = Counter(changes)
    counts.update(item.rule for item in manual)
    return dict(sorted(counts.items()))
