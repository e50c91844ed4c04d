"""What applies to one Mint file: the defaults, its settings file, then the command line (or the editor).

Each value keeps where it came from (``default``, ``mint.toml:3``,
``--select``), which ``mint check --show-settings`` prints. Codes are
selected with ruff's words: ``select`` is the set of codes checked (the
command line's replaces the file's, and the file's ``extend-select`` with it),
``extend-select`` adds to it, and every ``ignore`` applies, the file's and
the command line's, as do the ``per-file-ignores`` whose glob matches the
file: an ignore written in the project stays ignored whatever is selected.
Folders are walked as ruff walks them: ``exclude`` (the tool folders by
default; ``--exclude`` replaces it) and every ``extend-exclude`` leave out the
files and folders their globs match, and ``force-exclude`` the paths named too.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Mapping
from dataclasses import field, replace
from fnmatch import translate
from functools import cache
from pathlib import Path
from typing import Generic, TypeVar

from mintlang.codes import DEFAULT_SELECT, selector
from mintlang.dialect import Dialect
from mintlang.keyworddb.model import Controller
from mintlang.pairing import CONFIGURATION_SUFFIX, DEFAULT_PATTERN, Pairing, partner_on_disk
from mintlang.records import record
from mintlang.semantic.units import Unit
from mintlang.settings.files import Table

T = TypeVar("T")
DEFAULT = "default"
TOOL_TABLES = ("run", "migrate", "format")  # each tool's own options, read by the tool
EXCLUDE_KEYS = ("exclude", "extend-exclude")


@record
class Given(Generic[T]):
    """A value and where it came from."""

    value: T
    origin: str = DEFAULT

    @property
    def chosen(self) -> bool:
        """Whether someone chose the value (a settings file, the command line), not the default."""
        return self.origin != DEFAULT


def selectors(items: object) -> tuple[str, ...]:
    """Codes or code prefixes as ``--select`` reads them (``mintlang.codes.selector``).

    Raises ValueError for one that selects nothing, TypeError for something other than a list of strings.
    """
    if not isinstance(items, list | tuple) or not all(isinstance(item, str) for item in items):
        raise TypeError('must be a list of codes or code prefixes, such as ["E2", "W103"]')
    if not all(item.strip() for item in items):  # not ALL, nor no entry: --select "" is refused too
        raise ValueError("a blank entry selects no code: remove it, or write ALL for every code")
    return tuple(selector(item) for item in items)


def _choice(kind: type[Controller] | type[Dialect]) -> Callable[[object], Controller | Dialect]:
    def convert(value: object) -> Controller | Dialect:
        choices = [member.value for member in kind]
        if value not in choices:
            raise ValueError(f"{value!r} is not one of {', '.join(choices)}")
        return kind(value)

    return convert


def _pairing(value: object) -> str | None:
    """``config-pairing``: a name with ``<name>`` in it, or false for no pairing."""
    if value is False:
        return None
    if not isinstance(value, str):
        raise TypeError('must be a file name with <name> in it (such as "<name>.cfg"), or false')
    if Pairing.from_pattern(value) is None:
        raise ValueError(f"{value!r} has no <name>: write false to turn pairing off")
    return value


def _globs(value: object) -> tuple[str, ...]:
    if not isinstance(value, list) or not all(isinstance(item, str) and item for item in value):
        raise TypeError('must be a list of globs, such as ["legacy", "vendor/*.mnt"]')
    return tuple(value)


def _flag(value: object) -> bool:
    if not isinstance(value, bool):
        raise TypeError("must be true or false")
    return value


def _path(value: object) -> str:
    if not isinstance(value, str) or not value:
        raise TypeError("must be the path of a configuration file")
    return value


_CONVERTERS: dict[str, Callable[[object], object]] = {
    "controller": _choice(Controller),
    "dialect": _choice(Dialect),
    "select": selectors,
    "extend-select": selectors,
    "ignore": selectors,
    "config-pairing": _pairing,
    "config": _path,
    "exclude": _globs,
    "extend-exclude": _globs,
    "force-exclude": _flag,
}
KNOWN_KEYS = (*_CONVERTERS, "per-file-ignores", *TOOL_TABLES)


@record
class ProjectSettings:
    """One settings file's ``[tool.mint]`` (or ``mint.toml``), checked and converted."""

    table: Table
    values: Mapping[str, Given[object]]
    per_file_ignores: tuple[tuple[str, Given[tuple[str, ...]]], ...]  # glob -> codes

    @property
    def folder(self) -> Path:
        """What relative paths and globs in the file are relative to."""
        return self.table.path.parent

    @classmethod
    def from_table(cls, table: Table) -> ProjectSettings:
        """Raises SettingsError at the first key that is unknown or has a bad value."""
        unknown = [key for key in table.values if key not in KNOWN_KEYS]
        if unknown:
            raise table.error(f"unknown key (known: {', '.join(KNOWN_KEYS)})", unknown[0], key_at_fault=True)
        values = {key: Given(_converted(table, key, convert), table.origin(key)) for key, convert in _converts(table)}
        if "config" in values:
            values["config"] = Given(table.relative("config", str(values["config"].value)), values["config"].origin)
        for key in EXCLUDE_KEYS:
            if key in values:
                values[key] = Given(relative_globs(values[key].value, table.path.parent), values[key].origin)
        for name in TOOL_TABLES:
            table.table(name)  # its keys are its tool's options (mintlang.cli.settings); this checks it is a table
        ignores = table.table("per-file-ignores")
        globs = tuple(
            (glob, Given(_converted(ignores, glob, selectors), ignores.origin(glob))) for glob in ignores.values
        )
        return cls(table, values, globs)

    def tool(self, name: str) -> Table:
        """A tool's own table (``run``, ``migrate``)."""
        return self.table.table(name)


def _converts(table: Table) -> list[tuple[str, Callable[[object], object]]]:
    return [(key, convert) for key, convert in _CONVERTERS.items() if key in table.values]


def _converted(table: Table, key: str, convert: Callable[[object], object]) -> object:
    try:
        return convert(table.values[key])
    except (TypeError, ValueError) as error:
        raise table.error(str(error), key) from None


@record
class Glob:
    """An ``exclude`` glob and the folder a path is taken relative to when it is matched: the settings file's,
    or the current folder for the command line's, as ruff reads them."""

    pattern: str
    folder: Path


def relative_globs(patterns: tuple[str, ...], folder: Path) -> tuple[Glob, ...]:
    return tuple(Glob(pattern, folder) for pattern in patterns)


# ruff's default ``exclude`` less its Python-only folders (.eggs, __pypackages__ ...), and __pycache__: folders
# of tools and copies, where a .mnt file is a build's or a package's, not the project's own
DEFAULT_EXCLUDE = relative_globs(
    (
        ".bzr", ".direnv", ".git", ".hg", ".mypy_cache", ".nox", ".pytest_cache", ".ruff_cache", ".svn", ".tox",
        ".venv", ".vscode", "__pycache__", "_build", "build", "dist", "node_modules", "site-packages", "venv",
    ),
    Path(),
)  # fmt: skip


@record
class FileSettings:
    """What applies to one file, each value with its origin."""

    controller: Given[Controller] = Given(Controller.NEXTMOVE_PCI)
    dialect: Given[Dialect] = Given(Dialect.V4)
    select: Given[tuple[str, ...] | None] = Given(None)
    extend_select: Given[tuple[str, ...]] = Given(())
    ignore: Given[tuple[str, ...]] = Given(())
    per_file_ignores: tuple[tuple[str, Given[tuple[str, ...]]], ...] = ()  # the globs that match the file
    config_pairing: Given[str | None] = Given(DEFAULT_PATTERN)
    config: Given[Path | None] = Given(None)
    exclude: Given[tuple[Glob, ...]] = Given(DEFAULT_EXCLUDE)
    extend_exclude: Given[tuple[Glob, ...]] = Given(())
    force_exclude: Given[bool] = Given(False)
    project: ProjectSettings | None = field(default=None, compare=False)

    @property
    def selected(self) -> tuple[str, ...] | None:
        """The codes and prefixes checked; None: the analyser's default (errors and warnings)."""
        if not self.extend_select.value:
            return self.select.value
        return (*(self.select.value or DEFAULT_SELECT), *self.extend_select.value)

    @property
    def ignored(self) -> tuple[str, ...]:
        return (*self.ignore.value, *(code for _, given in self.per_file_ignores for code in given.value))

    def excludes(self, path: Path) -> bool:
        """Whether ``exclude`` or ``extend-exclude`` leaves ``path`` (a file or a folder) out of a folder walk."""
        return any(
            _matches_any(patterns, path, folder)
            for folder, patterns in _by_folder((*self.exclude.value, *self.extend_exclude.value))
        )

    @property
    def pairing(self) -> str | None:
        """The pairing pattern in force; None when a configuration file is named outright or pairing is off."""
        return None if self.config.value is not None else self.config_pairing.value

    def partner(self, path: Path) -> tuple[Unit, Path | None]:
        """Which file of its application ``path`` is, and the other one: for a program, the configuration it sees
        (``config``, else the file ``config-pairing`` names beside it if there is one); for a configuration file
        named ``*.cfg`` or as the pairing names it, its program if there is one."""
        configuration = path.suffix.lower() == CONFIGURATION_SUFFIX
        if self.config.value is not None:
            return (Unit.CONFIGURATION, None) if configuration else (Unit.PROGRAM, self.config.value)
        unit, other = partner_on_disk(path, self.pairing) if self.pairing is not None else (Unit.PROGRAM, None)
        return (Unit.CONFIGURATION if configuration else unit), other

    def rows(self) -> list[tuple[str, str, str]]:
        """(setting, value, origin) for each setting, as ``--show-settings`` lists them."""
        selected = self.selected
        rows = [
            ("controller", self.controller.value.value, self.controller.origin),
            ("dialect", self.dialect.value.value, self.dialect.origin),
            ("select", _listed(self.select.value, DEFAULT_SELECT), self.select.origin),
            ("extend-select", _listed(self.extend_select.value), self.extend_select.origin),
            ("ignore", _listed(self.ignore.value), self.ignore.origin),
            *(
                ("per-file-ignores", f"{glob}: {_listed(given.value)}", given.origin)
                for glob, given in self.per_file_ignores
            ),
            ("config-pairing", _pairing_shown(self.config_pairing.value), self.config_pairing.origin),
            ("config", str(self.config.value) if self.config.value else "none", self.config.origin),
            ("exclude", _globs_shown(self.exclude.value), self.exclude.origin),
            ("extend-exclude", _globs_shown(self.extend_exclude.value), self.extend_exclude.origin),
            ("force-exclude", "true" if self.force_exclude.value else "false", self.force_exclude.origin),
        ]
        if selected != self.select.value:
            rows.insert(5, ("codes checked", _listed(selected), "select + extend-select"))
        return rows


def _globs_shown(globs: tuple[Glob, ...]) -> str:
    """The globs as written; ruff's list of tools' folders by its name, which is too long for a row."""
    if globs == DEFAULT_EXCLUDE:
        return f"{len(globs)} tools' folders (.git, build ...)"
    return ", ".join(glob.pattern for glob in globs) or "none"


def _listed(codes: tuple[str, ...] | None, default: tuple[str, ...] = ()) -> str:
    """The selectors as written: ``ALL`` for the empty prefix ``--select ALL`` makes."""
    return ", ".join(code or "ALL" for code in (codes if codes is not None else default)) or "none"


def _pairing_shown(pattern: str | None) -> str:
    return "off" if pattern is None else pattern


@record
class Overrides:
    """What the command line (or the editor) says, above the settings file; None: not said."""

    controller: Given[Controller] | None = None
    dialect: Given[Dialect] | None = None
    select: Given[tuple[str, ...]] | None = None
    extend_select: Given[tuple[str, ...]] | None = None
    ignore: Given[tuple[str, ...]] | None = None
    config_pairing: Given[str | None] | None = None
    config: Given[Path | None] | None = None
    exclude: Given[tuple[Glob, ...]] | None = None
    extend_exclude: Given[tuple[Glob, ...]] | None = None
    force_exclude: Given[bool] | None = None


_REPLACED = ("controller", "dialect", "select", "extend_select", "config_pairing", "config", "exclude", "force_exclude")


def resolve(path: Path, project: ProjectSettings | None, overrides: Overrides) -> FileSettings:
    """The settings for ``path``: the defaults, then ``project`` (its settings file), then ``overrides``."""
    settings = FileSettings() if project is None else _from_project(path, project)
    changes: dict[str, object] = {name: given for name in _REPLACED if (given := getattr(overrides, name)) is not None}
    if overrides.select is not None and overrides.extend_select is None:
        changes["extend_select"] = Given((), overrides.select.origin)  # the command line's select is the whole set
    if overrides.select is None and overrides.extend_select is not None:  # besides the file's, as ruff adds it
        changes["extend_select"] = Given(
            (*settings.extend_select.value, *overrides.extend_select.value),
            _joined(settings.extend_select, overrides.extend_select),
        )
    if overrides.ignore is not None:
        changes["ignore"] = Given(
            (*settings.ignore.value, *overrides.ignore.value), _joined(settings.ignore, overrides.ignore)
        )
    if overrides.extend_exclude is not None:
        changes["extend_exclude"] = Given(
            (*settings.extend_exclude.value, *overrides.extend_exclude.value),
            _joined(settings.extend_exclude, overrides.extend_exclude),
        )
    return replace(settings, **changes)


def _joined(first: Given[tuple[object, ...]], second: Given[tuple[object, ...]]) -> str:
    return second.origin if not first.value else f"{first.origin}, {second.origin}"


def _from_project(path: Path, project: ProjectSettings) -> FileSettings:
    values = project.values
    changes = {key.replace("-", "_"): given for key, given in values.items()}
    matched = tuple((glob, given) for glob, given in project.per_file_ignores if _matches(glob, path, project.folder))
    return FileSettings(**changes, per_file_ignores=matched, project=project)  # type: ignore[arg-type]


def _matches(glob: str, path: Path, folder: Path) -> bool:
    """A ``per-file-ignores`` glob against the path relative to the settings file's folder, or the file's name;
    one that starts with ``!`` matches the files the rest does not, as ruff's does."""
    if glob.startswith("!"):
        return not _matches_any((glob[1:],), path, folder)
    return _matches_any((glob,), path, folder)


def _matches_any(globs: tuple[str, ...], path: Path, folder: Path) -> bool:
    """Whether one of ``globs`` matches the path relative to ``folder``, or its name; without regard to case, as
    Mint's file names are compared. ``*`` matches across folders, and a leading ``./`` names ``folder``, as in
    ruff's globs. The globs are one expression, and the path's two names made once: a walk asks of every file."""
    absolute, top = os.path.abspath(path), os.path.join(os.path.abspath(folder), "")  # a third of pathlib's cost
    names = [path.name.lower()]
    if absolute.startswith(top) or absolute + os.sep == top:
        names.append(absolute[len(top) :].replace(os.sep, "/").lower() or ".")
    expression = _expression(globs)
    return any(expression.match(name) for name in names)


@cache
def _expression(globs: tuple[str, ...]) -> re.Pattern[str]:
    """The globs as fnmatch reads each of their ``_spellings`` (its ``fnmatchcase`` is this match), in one."""
    spellings = (spelling for glob in globs for spelling in _spellings(glob.lower().removeprefix("./")))
    return re.compile("|".join(translate(spelling) for spelling in spellings))


@cache
def _by_folder(globs: tuple[Glob, ...]) -> tuple[tuple[Path, tuple[str, ...]], ...]:
    """The patterns of ``globs`` for each folder they are relative to."""
    folders = dict.fromkeys(glob.folder for glob in globs)
    return tuple((folder, tuple(glob.pattern for glob in globs if glob.folder == folder)) for folder in folders)


def _spellings(pattern: str) -> list[str]:
    """The glob as fnmatch reads it, and with each ``**/`` left out: in a glob ``**/`` is zero or more folders
    (``legacy/**/*.mnt`` matches ``legacy/old.mnt``), where fnmatch's needs at least one."""
    head, recursive, tail = pattern.partition("**/")
    if not recursive:
        return [pattern]
    return [head + spelt for rest in _spellings(tail) for spelt in (recursive + rest, rest)]
