"""Project settings for every tool: ``mint.toml``, or ``[tool.mint]`` in ``pyproject.toml``.

``settings_for(path)`` is what applies to one Mint file: the nearest settings
file above it (``files``), checked and layered under the command line's or the
editor's own (``model``). Each tool's table (``[tool.mint.run]``,
``[tool.mint.migrate]``) is handed to that tool, which knows its options.
"""

from __future__ import annotations

from pathlib import Path

from mintlang.settings.files import SettingsError, Table, find_settings
from mintlang.settings.model import FileSettings, Given, Overrides, ProjectSettings, resolve, selectors

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


__all__ = [
    "FileSettings",
    "Given",
    "Overrides",
    "ProjectSettings",
    "SettingsError",
    "Table",
    "project_for",
    "selectors",
    "settings_for",
]
