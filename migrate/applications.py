"""The applications of a run, read and migrated one by one.

An application is a program, its configuration file, or both: what the migrator
reads together. Each is migrated on its own, so that a bug a rule meets in one
(``MigrationFailed``, or anything else a bug raises) is reported with its files'
paths and the rule, those files are left as they were, and the others are
migrated and written as if nothing had happened. So is a file that cannot be read as
Mint text (a NUL byte, a read error): it fails its application, named with where.
"""

from __future__ import annotations

from pathlib import Path

from mintlang.cli.files import (
    CONFIGURATION_SUFFIXES,
    PROGRAM_SUFFIXES,
    cannot_read,
    find,
    identity,
    is_configuration,
    program_as_own_configuration,
)
from mintlang.migrate import mintmt
from mintlang.migrate.api import migrate
from mintlang.migrate.model import MigrationFailed, NotRead
from mintlang.migrate.report import FileEntry
from mintlang.records import record
from mintlang.semantic.units import Unit
from mintlang.settings import Overrides, SettingsError, settings_for
from mintlang.source import SourceFile, read_source


class UsageError(Exception):
    """A problem with the command line or a file: reported in one line, exit status 2."""


@record
class Migrated:
    """A file of an application with its report entry (whose result is None if it failed; ``file`` is None
    for a file that could not be read at all)."""

    file: SourceFile | None
    entry: FileEntry


@record
class Unread:
    """A file of an application that could not be read as Mint text, and why."""

    path: Path
    role: str
    failure: NotRead


@record(slots=False)
class Application:
    """One program, its configuration file, or both; a file of it that could not be read is in ``unread``,
    and the application is then not migrated: the two files are one application, as the controller runs
    them, and either migrated alone would be migrated wrongly (its ``AXES``, its defaults, its names)."""

    program: SourceFile | None
    configuration: SourceFile | None
    unread: tuple[Unread, ...] = ()

    def files(self) -> list[tuple[SourceFile, str]]:
        """Each file read with its role, the configuration file first (it runs first)."""
        found = [(self.configuration, "configuration"), (self.program, "program")]
        return [(file, role) for file, role in found if file is not None]

    def paths(self) -> list[Path]:
        """The path of each file, read or not."""
        return [unread.path for unread in self.unread] + [file.path for file, _ in self.files()]

    def migrate(
        self,
        controller: str,
        only: tuple[str, ...] | None,
        skip: tuple[str, ...],
        opt_in: tuple[str, ...],
        *,
        to: str = "v4",
    ) -> list[Migrated]:
        """The application migrated to Mint v4 (from v3) or, ``to`` ``"mintmt"``, to MintMT (from v4)."""
        if self.unread:
            return self._not_read()
        config = self.configuration.text if self.configuration is not None else None
        program = self.program.text if self.program is not None else ""
        try:
            if to == "mintmt":
                result = mintmt.to_mintmt(program, config=config, controller=controller)
            else:
                result = migrate(program, config=config, controller=controller, only=only, skip=skip, opt_in=opt_in)
        except MigrationFailed as failure:
            return self._failed(failure)
        except Exception as error:  # a bug outside the rules: still this application's alone
            return self._failed(MigrationFailed(None, f"{type(error).__name__}: {error}"))
        results = {"configuration": result.configuration, "program": result}
        return [Migrated(file, FileEntry(str(file.path), role, results[role])) for file, role in self.files()]

    def _failed(self, failure: MigrationFailed) -> list[Migrated]:
        return [Migrated(file, FileEntry(str(file.path), role, None, failure)) for file, role in self.files()]

    def _not_read(self) -> list[Migrated]:
        """Each file unread with why, each other file with the one it is not migrated without, in ``files``' order."""
        missing = self.unread[0]
        failure = NotRead(f"its {_ROLES[missing.role]} {missing.path} cannot be read")
        items = [Migrated(file, FileEntry(str(file.path), role, None, failure)) for file, role in self.files()]
        items += [Migrated(None, FileEntry(str(file.path), file.role, None, file.failure)) for file in self.unread]
        return sorted(items, key=lambda item: item.entry.role != "configuration")


_ROLES = {"program": "program", "configuration": "configuration file"}


@record
class Unlooked:
    """A path the command line names that could not be looked at (a missing path, a folder that cannot be
    listed, a dangling link): the line that says so, and its report entry, a failed file, so that the
    report (``--format json`` too) names it beside the files migrated."""

    line: str
    item: Migrated


@record
class Found:
    """The applications the command line names, and the paths that could not be looked at, which the others
    do not wait for."""

    applications: list[Application]
    unread: list[Unlooked]


def read(
    paths: tuple[Path, ...], config: Path | None, *, paired: bool = True, overrides: Overrides | None = None
) -> Found:
    """The applications the command line names: each program with the configuration file paired with it
    (none unless ``paired``), or one with ``config``; the folders searched leave out what the settings, under
    ``overrides``, exclude."""
    # a folder's configuration files too: one that no program claims is migrated alone, not left in v3
    suffixes = PROGRAM_SUFFIXES if config is not None else PROGRAM_SUFFIXES | CONFIGURATION_SUFFIXES
    found = find(paths, suffixes, overrides)
    unread = [_unlooked(error) for error in found.unreadable]
    if config is not None:
        if len(found.files) > 1 or any(is_configuration(path) for path in found.files):
            raise UsageError("--config pairs one configuration file with one program file")
        itself = program_as_own_configuration(found.files, config)
        if itself is not None:  # read in both roles; with --write the second write would undo the first
            raise UsageError(f"--config {config} is the program {itself} itself: name the configuration file")
        if unread:  # the program named with --config: nothing else to migrate
            raise UsageError(unread[0].line)
        return Found([_application(found.files[0] if found.files else None, config)], [])
    if not found.files and not found.excluded:  # a path force-exclude leaves out is nothing to migrate, no error
        named = ", ".join(str(path) for path in paths)
        raise UsageError(unread[0].line if unread else f"no .mnt or .cfg files to migrate in {named}")
    partners = _partners(found.files) if paired else {}
    claimed = {identity(configuration) for configuration in partners.values()}
    applications = [
        _application(None, path) if is_configuration(path) else _application(path, partners.get(path))
        for path in found.files
        if not (is_configuration(path) and identity(path) in claimed)
    ]
    return Found(applications, unread)


def _unlooked(error: OSError) -> Unlooked:
    path = str(error.filename)
    why = "no such file or directory" if isinstance(error, FileNotFoundError) else f"cannot be read ({error.strerror})"
    role = "folder" if Path(path).is_dir() else "configuration" if is_configuration(Path(path)) else "program"
    return Unlooked(cannot_read(error), Migrated(None, FileEntry(path, role, None, NotRead(why))))


def _partners(found: list[Path]) -> dict[Path, Path]:
    """Each program with the configuration file paired with it (``mintlang.pairing``, as ``mint check`` and
    ``mint-run`` pair them): the two are one application, as the controller runs them. A configuration file
    goes with the first program that pairs with it; one named that no program claims is migrated alone."""
    partners: dict[Path, Path] = {}
    taken: set[object] = set()
    for program in (path for path in found if not is_configuration(path)):
        try:
            unit, partner = settings_for(program).partner(program)
        except SettingsError as error:
            raise UsageError(str(error)) from None
        if unit is not Unit.PROGRAM or partner is None or identity(partner) in taken:
            continue
        partners[program] = partner
        taken.add(identity(partner))
    return partners


def _application(program: Path | None, configuration: Path | None) -> Application:
    """The application of these files, read; a file that cannot be read is kept as ``Unread``."""
    read = [(role, path, _read(path)) for role, path in (("configuration", configuration), ("program", program))]
    files = {role: file for role, _, file in read if isinstance(file, SourceFile)}
    unread = tuple(Unread(path, role, file) for role, path, file in read if isinstance(file, NotRead) and path)
    return Application(files.get("program"), files.get("configuration"), unread)


def _read(path: Path | None) -> SourceFile | NotRead | None:
    if path is None:
        return None
    try:
        file = read_source(path)
    except OSError as error:
        return NotRead(f"cannot be read ({error.strerror or error})")
    position = file.nul()
    return file if position is None else NotRead(file.not_text(), position)
