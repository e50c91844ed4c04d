"""``mint check --fix``, ``--unsafe-fixes``, ``--diff`` and ``--add-ignore``: fixing the checked programs, as ruff
does, or silencing their findings.

Each worker fixes its program round after round (``mintlang.fixes``), or
silences its findings (``mintlang.analysis.silencing``), and reports what the
new text still has; here the new texts are written, each
atomically and only if the file still holds what was read (``mintlang.atomic``),
or shown as unified diffs without writing. A configuration file is reported but
not fixed: its findings depend on every program that sees it. ``--add-ignore``
silences them too, as the run's programs see them (``Plan.silenced_configurations``):
a comment changes nothing any program runs.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable, Collection, Sequence
from dataclasses import field, replace
from pathlib import Path
from typing import IO, TypeVar

import click

from mintlang import atomic
from mintlang.cli.checking import FileFixed, Fixing, Job
from mintlang.cli.diffs import unified, write_diff
from mintlang.cli.report import FileReport
from mintlang.diagnostics import LineIndex
from mintlang.fixes import MAX_ROUNDS, automatic_fix, why_left_out
from mintlang.records import record

F = TypeVar("F", bound=Callable[..., object])


@record(frozen=False, slots=False)
class Outcome:
    """What a fixing run did: counts by code, the files changed, and what could not be written."""

    codes: Counter[str] = field(default_factory=Counter)
    files: int = 0
    problems: list[str] = field(default_factory=list)
    unconverged: list[str] = field(default_factory=list)
    unwritten: set[Path] = field(default_factory=set)  # files whose fixed text could not be written

    def notes(self) -> list[str]:
        """The files whose fixes did not settle: a fix that undoes another, or more rounds than allowed."""
        return [f"{path}: fixes still apply after {MAX_ROUNDS} rounds; run --fix again" for path in self.unconverged]


def unified_diff(file: FileFixed) -> str:
    """The change as ``diff -u`` shows it, the file's name on both sides."""
    name = str(file.original.path)
    return unified(file.original.text, file.fixed.text, name, name)


def _write(file: FileFixed) -> str | None:
    """Write the fixed text over the file; the one line saying why not, if it could not be."""
    original = file.original
    try:
        real = atomic.target(original.path)
        atomic.write(real, original.encode(file.fixed.text), original.encode())
    except atomic.Unwritable as error:
        return f"{error}; not fixed"
    except atomic.Stale:
        return f"{original.path} changed while it was checked; not fixed"
    except OSError as error:
        return f"cannot write {original.path}: {error.strerror or error}; not fixed"
    return None


def apply(files: Sequence[FileFixed], *, diff: IO[str] | None) -> Outcome:
    """Write each changed file, or with ``diff`` show its change there instead."""
    outcome = Outcome()
    for file in files:
        if not file.fixed.converged:
            outcome.unconverged.append(str(file.original.path))
        if not file.changed:
            continue
        problem = None if diff is not None else _write(file)
        if diff is not None:
            write_diff(diff, unified_diff(file), file.original.encoding)
        if problem is not None:
            outcome.problems.append(problem)
            outcome.unwritten.add(file.original.path)
            continue
        outcome.files += 1
        outcome.codes.update(diagnostic.code for diagnostic in file.fixed.fixed)
    return outcome


def _plural(count: int, word: str) -> str:
    return f"{count} {word}{'s' if count != 1 else ''}"


def fixed_summary(outcome: Outcome, *, diff: bool, silencing: bool = False) -> str:
    """One line: what was fixed (or would be, with ``diff``; or silenced by comments) and in how many files, by
    code, and how many files with fixes could not be written (standard error says why)."""
    total = sum(outcome.codes.values())
    unwritten = (
        f"{_plural(len(outcome.unwritten), 'file')} with fixes could not be written" if outcome.unwritten else ""
    )
    if not total:
        done, to_do = ("silenced", "silence") if silencing else ("fixed", "fix")
        return f"Nothing {done}: {unwritten}." if unwritten else f"Nothing to {to_do}."
    codes = ", ".join(f"{count} {code}" for code, count in sorted(outcome.codes.items()))
    verb = "Would fix" if diff else "Silenced" if silencing else "Fixed"
    fixed = f"{verb} {_plural(total, 'finding')} in {_plural(outcome.files, 'file')} ({codes})"
    return f"{fixed}; {unwritten}." if unwritten else f"{fixed}."


def fixable_summary(reports: Sequence[FileReport], *, unsafe_fixes: bool = False) -> list[str]:
    """How many of the findings ``--fix`` would fix, and how many more ``--unsafe-fixes`` (given, it opts in as
    ruff's does: all are counted together); then, for each reason, where the fixes it sets aside are
    (``FileReport.left_out``): they are not counted, as it does not apply them."""
    safe = unsafe = 0  # counted in one pass: a report's diagnostics are made as they are read
    set_aside: dict[str, list[str]] = {}  # why -> where
    for report in reports:
        reasons = dict(report.left_out)
        index = LineIndex(report.source) if reasons else None
        for diagnostic in report.diagnostics:
            fix = automatic_fix(diagnostic, unsafe=True)
            why = why_left_out(reasons, diagnostic) if fix is not None else None
            if why is not None and index is not None:  # a reason is only given where there are some
                at = index.position(diagnostic.span.start)
                set_aside.setdefault(why, []).append(f"{report.path}:{at.line}:{at.column} {diagnostic.code}")
            elif fix is not None:
                safe += fix.safe
                unsafe += not fix.safe
    lines = [f"Set aside by --fix, as {why}: {', '.join(where)}." for why, where in set_aside.items()]
    if unsafe_fixes:  # the user opted in: every fix counted is one that --fix --unsafe-fixes makes
        safe, unsafe = 0, safe + unsafe
    more = f" ({unsafe} more with --unsafe-fixes)" if unsafe else ""
    if safe:
        return [f"{_plural(safe, 'finding')} fixable with --fix{more}.", *lines]
    if unsafe:
        return [f"{_plural(unsafe, 'finding')} fixable with --fix --unsafe-fixes.", *lines]
    return lines


def fix_options() -> Callable[[F], F]:
    """``--fix``, ``--unsafe-fixes``, ``--diff`` and ``--add-ignore``, as ruff spells them (``--add-noqa``)."""
    options = [
        click.option("--fix", is_flag=True, help="Apply the safe fixes to the programs, and report what is left."),
        click.option(
            "--unsafe-fixes",
            is_flag=True,
            help="With --fix or --diff, apply the unsafe fixes too (guesses at the intent: review them); alone, count"
            " them as fixable.",
        ),
        click.option(
            "--diff",
            is_flag=True,
            help="Show the fixes as a unified diff instead of writing them (exit 1 if there are any).",
        ),
        click.option(
            "--add-ignore",
            "--add-noqa",
            "add_ignore",
            is_flag=True,
            help="Silence every finding of the files with a 'REM mint: ignore[...]' comment on its line, to "
            "adopt the checker on programs as they stand (ruff's --add-noqa).",
        ),
    ]

    def decorate(function: F) -> F:
        for option in reversed(options):
            function = option(function)
        return function

    return decorate


def marked(jobs: Sequence[Job], hidden: Collection[int], fixing: Fixing) -> list[Job]:
    """The jobs, each program the run reports to be fixed (not one checked only for its configuration file)."""
    return [job if index in hidden else replace(job, fixing=fixing) for index, job in enumerate(jobs)]
