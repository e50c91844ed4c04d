"""Finding the files a command was asked to look at.

No problem is skipped: a directory that cannot be read, a dangling link or a
link loop below a named directory would otherwise leave programs unchecked (or
unmigrated) without a word. ``find`` keeps each one to be reported while the
other files are checked (or migrated).
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path

from mintlang.records import record
from mintlang.source import NOT_TEXT, SourceFile

PROGRAM_SUFFIXES = frozenset({".mnt"})
CONFIGURATION_SUFFIXES = frozenset({".cfg"})


@record
class Found:
    """The files to look at, and the paths that could not be looked at (each error names its path)."""

    files: list[Path]
    unreadable: list[OSError]


def _programs_below(directory: Path, unreadable: list[OSError], suffixes: frozenset[str]) -> list[Path]:
    """The files below ``directory`` named with ``suffixes``, sorted; what could not be read is added to
    ``unreadable`` sorted by path as well, so the problems are reported in the order of the files."""
    found: list[Path] = []
    failed: list[OSError] = []
    for folder, _, names in os.walk(directory, onerror=failed.append):
        for name in names:
            path = Path(folder, name)
            if path.suffix.lower() in suffixes:
                try:
                    path.stat()  # a dangling link or a loop raises here
                except OSError as error:
                    failed.append(error)
                    continue
                found.append(path)
    unreadable.extend(sorted(failed, key=lambda error: Path(str(error.filename))))
    return sorted(found)


def find(paths: Iterable[Path], suffixes: frozenset[str] = PROGRAM_SUFFIXES) -> Found:
    """Files named directly, and the ``.mnt`` files (``suffixes``) below named directories, sorted, each once
    under the name it was first found by; and what failed.

    A named ``.cfg`` file is checked as a configuration file on its own. A path that
    does not exist, a link loop or a folder that cannot be listed is an OSError
    (FileNotFoundError for a missing path) naming the path, kept to be reported.
    """
    files: list[Path] = []
    unreadable: list[OSError] = []
    for path in paths:
        try:
            path.stat()  # ELOOP, ENOTDIR and ENOENT say what is wrong; Path.exists() would hide them
        except OSError as error:
            unreadable.append(error)
            continue
        files.extend(_programs_below(path, unreadable, suffixes) if path.is_dir() else [path])
    once: dict[object, Path] = {}  # a file named twice (a.mnt, ../src/a.mnt) would be fixed twice, the second refused
    for file in files:
        once.setdefault(identity(file), file)
    return Found(list(once.values()), unreadable)


def identity(path: Path) -> object:
    """What names one file however it is spelt or linked (its device and inode); where it would be, if missing.

    One stat per file keeps pairing a folder of many programs linear, where comparing each pair was not."""
    try:
        status = path.stat()
    except OSError:
        return path.resolve()
    return status.st_dev, status.st_ino


def cannot_read(error: OSError) -> str:
    """One line for a path that could not be read."""
    if isinstance(error, FileNotFoundError):
        return f"no such file or directory: {error.filename or error.args[0]}"
    return f"cannot read {error.filename}: {error.strerror or error}"


@record
class Unchecked:
    """A path that was not checked, and why: said on standard error (``said``), and for ruff's E902 users an
    entry of the machine-readable reports, at 1:1 or where the problem is (a NUL byte)."""

    path: str
    reason: str
    said: str
    line: int = 1
    column: int = 1


def unread(error: OSError) -> Unchecked:
    """A path that could not be read (or looked at)."""
    path = str(error.filename or error.args[0])
    return Unchecked(path, error.strerror or str(error), cannot_read(error))


def not_text(source: SourceFile) -> Unchecked | None:
    """A file read but not Mint text (a NUL byte), placed at its first NUL byte; None for text."""
    position = source.nul()
    if position is None:
        return None
    said = f"{source.binary()}: not checked"
    return Unchecked(str(source.path), NOT_TEXT, said, position.line, position.column)


def is_configuration(path: Path) -> bool:
    return path.suffix.lower() in CONFIGURATION_SUFFIXES


def same_file(path: Path, other: Path) -> bool:
    """Whether two names reach one file (through links, or case-insensitive names); False if one is missing."""
    try:
        return path.samefile(other)
    except OSError:
        return False


def program_as_own_configuration(programs: Iterable[Path], configuration: Path) -> Path | None:
    """The program also named as ``--config``: read in both roles, its names would be declared twice."""
    return next((path for path in programs if not is_configuration(path) and same_file(path, configuration)), None)
