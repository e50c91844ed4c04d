"""``--write``: each changed file replaced atomically (``atomic``), and only while it still
holds what the migration read.

Every file to write is checked (``atomic.target``) before the first is written: a
read-only file or a device stops the run with nothing written. Then each
application is written on its own. If one of its files changed on disk since it
was read (an edit saved during the migration), none of its files is written, as
they were migrated together and the edit must not be lost; a file that cannot be
written is reported and the others go on. Each problem is one line naming the
file, and a last line says which files were not written.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from mintlang import atomic
from mintlang.atomic import Stale, Unwritable, target
from mintlang.migrate.applications import Migrated
from mintlang.migrate.report import plural
from mintlang.records import record
from mintlang.source import SourceFile


@record
class Written:
    """What ``--write`` did: the problems met (one line each) and the changed files it left as they were."""

    problems: tuple[str, ...]
    unwritten: frozenset[Path]


def write_changed(applications: Sequence[Sequence[Migrated]]) -> Written:
    """Write the changed files of each application."""
    try:
        plans = [
            [(target(file.path), file, text) for file, text in _changed(application)] for application in applications
        ]
    except Unwritable as error:
        everything = frozenset(file.path for application in applications for file, _ in _changed(application))
        return Written((f"{error}; nothing was written",), everything)
    problems: list[str] = []
    left: list[Path] = []
    for application, plan in zip(applications, plans, strict=True):
        if not plan:
            continue
        read = [item.file for item in application if item.file is not None]  # all of them: it was migrated
        stale = [str(file.path) for file in read if _content(file.path) != file.encode()]
        if stale:
            problems.append(f"{_changed_since(stale)}: not written, so the edit is kept; migrate again")
            left += [file.path for _, file, _ in plan]
            continue
        for real, file, text in plan:
            problem = _write(real, file, text)
            if problem is not None:
                problems.append(problem)
                left.append(file.path)
    if left:
        total = sum(len(plan) for plan in plans)
        names = ", ".join(map(str, left))
        problems.append(f"{total - len(left)} of {plural(total, 'file')} written; not written: {names}")
    return Written(tuple(problems), frozenset(left))


def _changed(application: Sequence[Migrated]) -> list[tuple[SourceFile, str]]:
    """The files the migration changed, with their new text."""
    changed = [(item.file, item.entry.result) for item in application]
    return [
        (file, result.text) for file, result in changed if file is not None and result is not None and result.changed
    ]


def _write(real: Path, file: SourceFile, text: str) -> str | None:
    """Write one file; None, or what went wrong."""
    try:
        atomic.write(real, file.encode(text), file.encode())
    except Stale:
        return f"{_changed_since([str(file.path)])}: not written, so the edit is kept; migrate again"
    except OSError as error:
        return f"cannot write {real}: {error.strerror or error}"
    return None


def _changed_since(paths: list[str]) -> str:
    return f"{', '.join(paths)} changed since {'it was' if len(paths) == 1 else 'they were'} read"


def _content(path: Path) -> bytes | None:
    try:
        return path.read_bytes()
    except OSError:
        return None
