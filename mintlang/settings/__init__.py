"""Project settings for every tool: ``mint.toml``, or ``[tool.mint]`` in ``pyproject.toml``.

``settings_for(path)`` is what applies to one Mint file: the nearest settings
file above it (``files``), checked and layered under the command line's or the
editor's own (``model``); ``folder_settings`` and ``force_excluded`` are what
a folder walk leaves out. Each tool's table (``[tool.mint.run]``,
``[tool.mint.migrate]``) is handed to that tool, which knows its options.
"""

from __future__ import annotations

import os
from pathlib import Path

from mintlang.settings.files import SettingsError, Table, find_settings
from mintlang.settings.model import (
    FileSettings,
    Given,
    Glob,
    Overrides,
    ProjectSettings,
    relative_globs,
    resolve,
    selectors,
)

_checked: dict[Path, tuple[Table, ProjectSettings]] = {}  # a settings file's table, checked once while it stays


def project_for(path: Path) -> ProjectSettings | None:
    """The checked settings of the nearest settings file above ``path``; raises SettingsError for a bad one."""
    table = find_settings(path)
    if table is None:
        return None
    kept = _checked.get(table.path)
    if kept is not None and kept[0] is table:  # the file's cached table: unchanged since it was checked
        return kept[1]
    project = ProjectSettings.from_table(table)
    _checked[table.path] = (table, project)
    return project


def settings_for(path: Path, overrides: Overrides | None = None) -> FileSettings:
    """What applies to the Mint file ``path``; raises SettingsError for a bad settings file."""
    return resolve(path, project_for(path), overrides or Overrides())


def folder_settings(folder: Path, overrides: Overrides | None = None) -> FileSettings:
    """What applies to the entries of ``folder`` as a walk lists them (``excludes``), as ruff judges an entry by
    the settings above it. A settings file that cannot be used excludes by the defaults here: the check (or
    migration, or test) of each file below it says what is wrong with it, with its place."""
    try:
        project = project_for(folder)
    except SettingsError:
        project = None
    return resolve(folder, project, overrides or Overrides())


def force_excluded(path: Path, overrides: Overrides | None = None) -> bool:
    """Whether ``force-exclude`` leaves out ``path``, named on the command line: it, or a folder above it below
    the settings file's folder (the current folder without one), is excluded, as ruff has it for pre-commit,
    which names the files it hands over. Without ``force-exclude`` a path named is looked at, as in ruff."""
    absolute = Path(os.path.abspath(path))
    settings = folder_settings(absolute.parent, overrides)
    if not settings.force_exclude.value:
        return False
    top = settings.project.folder if settings.project is not None else Path.cwd()
    for entry in (absolute, *absolute.parents):
        if entry == top or not entry.name:
            return False
        if folder_settings(entry.parent, overrides).excludes(entry):
            return True
    return False


__all__ = [
    "FileSettings",
    "Given",
    "Glob",
    "Overrides",
    "ProjectSettings",
    "SettingsError",
    "Table",
    "folder_settings",
    "force_excluded",
    "project_for",
    "relative_globs",
    "selectors",
    "settings_for",
]
