"""Finding the files a command was asked to look at."""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

PROGRAM_SUFFIXES = frozenset({".mnt"})
CONFIGURATION_SUFFIXES = frozenset({".cfg"})


def collect(paths: Iterable[Path]) -> list[Path]:
    """Files named directly, and the ``.mnt`` files below named directories, sorted.

    A named ``.cfg`` file is checked as a configuration file on its own.
    Raises FileNotFoundError for a path that does not exist.
    """
    found: list[Path] = []
    for path in paths:
        if path.is_dir():
            found.extend(sorted(p for p in path.rglob("*") if p.is_file() and p.suffix.lower() in PROGRAM_SUFFIXES))
        elif path.exists():
            found.append(path)
        else:
            raise FileNotFoundError(path)
    return list(dict.fromkeys(found))


def is_configuration(path: Path) -> bool:
    return path.suffix.lower() in CONFIGURATION_SUFFIXES
