"""Finding the files a command was asked to look at.

No problem is skipped: a directory that cannot be read, a dangling link or a
link loop below a named directory would otherwise leave programs unchecked (or
unmigrated) without a word. ``find`` keeps each one to be reported while the
other files are checked (or migrated).

What the settings exclude (``exclude``, ``extend-exclude``) is left out of a
walk, an excluded folder not entered; a path named is looked at unless
``force-exclude`` is set, as ruff finds its files.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Iterator
from pathlib import Path

from mintlang.records import record
from mintlang.settings import Overrides, folder_settings, force_excluded
from mintlang.source import NOT_TEXT, SourceFile

PROGRAM_SUFFIXES = frozenset({".mnt"})
CONFIGURATION_SUFFIXES = frozenset({".cfg"})


@record
class Found:
    """The files to look at, the paths that could not be looked at (each error names its path), and the paths
    named that ``force-exclude`` left out."""

    files: list[Path]
    unreadable: list[OSError]
    excluded: list[Path]


def walk(
    directory: Path,
    wanted: Callable[[str], bool],
    overrides: Overrides | None = None,
    onerror: Callable[[OSError], object] | None = None,
) -> Iterator[tuple[str, list[str]]]:
    """Each folder below ``directory`` (as ``os.walk`` lists it) with the names of its ``wanted`` files, less
    what the settings of the folder exclude; an excluded folder is not entered."""
    for folder, folders, names in os.walk(directory, onerror=onerror):
        settings = folder_settings(Path(folder), overrides)
        folders[:] = [name for name in folders if not settings.excludes(Path(folder, name))]
        yield folder, [name for name in names if wanted(name) and not settings.excludes(Path(folder, name))]


def _programs_below(
    directory: Path, unreadable: list[OSError], suffixes: frozenset[str], overrides: Overrides | None
) -> list[Path]:
    """The files below ``directory`` named with ``suffixes``, sorted; what could not be read is added to
    ``unreadable`` sorted by path as well, so the problems are reported in the order of the files."""
    found: list[Path] = []
    failed: list[OSError] = []

    def wanted(name: str) -> bool:
        return os.path.splitext(name)[1].lower() in suffixes

    for folder, names in walk(directory, wanted, overrides, failed.append):
        for name in names:
            path = Path(folder, name)
            try:
                path.stat()  # a dangling link or a loop raises here
            except OSError as error:
                failed.append(error)
                continue
            found.append(path)
    unreadable.extend(sorted(failed, key=lambda error: Path(str(error.filename))))
    return sorted(found)


def find(
    paths: Iterable[Path], suffixes: frozenset[str] = PROGRAM_SUFFIXES, overrides: Overrides | None = None
) -> Found:
    """Files named directly, and the ``.mnt`` files (``suffixes``) below named directories, sorted, each once
    under the name it was first found by, less what the settings (under ``overrides``) exclude; and what failed.

    A named ``.cfg`` file is checked as a configuration file on its own. A path that
    does not exist, a link loop or a folder that cannot be listed is an OSError
    (FileNotFoundError for a missing path) naming the path, kept to be reported; a
    path ``force-exclude`` leaves out is not looked at, as ruff does not.
    """
    files: list[Path] = []
    unreadable: list[OSError] = []
    excluded: list[Path] = []
    for path in paths:
        if force_excluded(path, overrides):
            excluded.append(path)
            continue
        try:
            path.stat()  # ELOOP, ENOTDIR and ENOENT say what is wrong; Path.exists() would hide them
        except OSError as error:
            unreadable.append(error)
            continue
        files.extend(_programs_below(path, unreadable, suffixes, overrides) if path.is_dir() else [path])
    once: dict[object, Path] = {}  # a file named twice (a.mnt, ../src/a.mnt) would be fixed twice, the second refused
    for file in files:
        once.setdefault(identity(file), file)
    return Found(list(once.values()), unreadable, excluded)


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
