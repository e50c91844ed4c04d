"""The files a run writes (``--trace``, ``--plot``), checked before the run starts.

A run can take a minute of wall time, so a path that cannot be written is
reported before it, not after. An output never replaces a file the run reads
(the program, its configuration, a scenario) or, for a trace, any existing
file that is not an earlier trace: a typo must not cost the user their program.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path

from mintlang.cli.files import same_file
from mintlang.runtime.trace import FIRST_COLUMN, image_types


class OutputProblem(Exception):
    """An output path that cannot or must not be written; the message names it and says why."""


def _same(path: Path, other: Path) -> bool:
    """One file, or two outputs not written yet that would be one (compared where they would be)."""
    return same_file(path, other) or path.resolve() == other.resolve()


def _writable(path: Path) -> None:
    if path.is_dir():
        raise OutputProblem(f"cannot write {path}: it is a directory")
    parent = path.parent
    if not parent.is_dir():
        reason = "not a directory" if parent.exists() else "no such directory"
        raise OutputProblem(f"cannot write {path}: {parent}: {reason}")
    if not os.access(path if path.exists() else parent, os.W_OK):
        raise OutputProblem(f"cannot write {path}: permission denied")


def _not_an_input(path: Path, inputs: Mapping[Path, str]) -> None:
    for source, role in inputs.items():
        if _same(path, source):
            raise OutputProblem(f"cannot write {path}: it is also {role}")


def check_trace(path: Path, inputs: Mapping[Path, str]) -> None:
    """Refuse a trace path that would replace an input (path to its role) or a file other than an earlier trace."""
    _writable(path)
    _not_an_input(path, inputs)
    if path.is_file() and path.stat().st_size:
        with path.open("rb") as existing:
            if not existing.read(len(FIRST_COLUMN) + 1) == f"{FIRST_COLUMN},".encode():
                raise OutputProblem(f"will not overwrite {path}: it exists and is not a trace; remove it first")


def check_report(path: Path, inputs: Mapping[Path, str]) -> None:
    """Refuse a report path that cannot be written or would replace an input (path to its role)."""
    _writable(path)
    _not_an_input(path, inputs)


def check_plot(path: Path, inputs: Mapping[Path, str]) -> None:
    """Refuse a plot path without an image extension matplotlib can write, or one that would replace an input.

    Raises ``PlotUnavailable`` when matplotlib is not installed.
    """
    _writable(path)
    _not_an_input(path, inputs)
    types = image_types()
    if path.suffix.lower().lstrip(".") not in types:
        listed = ", ".join(sorted(types))
        raise OutputProblem(f"cannot plot to {path}: name an image by its extension ({listed})")
