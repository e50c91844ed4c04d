"""Finding the files a command was asked to look at.

Every problem is raised, never skipped: a directory that cannot be read, a
dangling link or a link loop below a named directory would otherwise leave
programs unchecked (or unmigrated) without a word.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path

PROGRAM_SUFFIXES = frozenset({".mnt"})
CONFIGURATION_SUFFIXES = frozenset({".cfg"})


def _raise(error: OSError) -> None:
    raise error


def _programs_below(directory: Path) -> list[Path]:
    found: list[Path] = []
    for folder, _, names in os.walk(directory, onerror=_raise):
        for name in names:
            path = Path(folder, name)
            if path.suffix.lower() in PROGRAM_SUFFIXES:
                path.stat()  # a dangling link or a loop raises here
                found.append(path)
    return sorted(found)


def collect(paths: Iterable[Path]) -> list[Path]:
    """Files named directly, and the ``.mnt`` files below named directories, sorted.

    A named ``.cfg`` file is checked as a configuration file on its own. Raises
    OSError (FileNotFoundError for a path that does not exist) with the path that failed.
    """
    found: list[Path] = []
    for path in paths:
        path.stat()  # ELOOP, ENOTDIR and ENOENT say what is wrong; Path.exists() would hide them
        found.extend(_programs_below(path) if path.is_dir() else [path])
    return list(dict.fromkeys(found))


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
