"""The applications of a run, read and migrated one by one.

An application is a program, its configuration file, or both: what the migrator
reads together. Each is migrated on its own, so that a bug a rule meets in one
(``MigrationFailed``, or anything else a bug raises) is reported with its files'
paths and the rule, those files are left as they were, and the others are
migrated and written as if nothing had happened.
"""

from __future__ import annotations

from pathlib import Path

from mintlang.cli.files import collect, is_configuration, program_as_own_configuration
from mintlang.migrate import mintmt
from mintlang.migrate.api import migrate
from mintlang.migrate.model import MigrationFailed
from mintlang.migrate.report import FileEntry
from mintlang.records import record
from mintlang.semantic.units import Unit
from mintlang.settings import SettingsError, settings_for
from mintlang.source import SourceFile, read_source


class UsageError(Exception):
    """A problem with the command line or a file: reported in one line, exit status 2."""


@record
class Migrated:
    """A file of an application with its report entry (whose result is None if it failed)."""

    file: SourceFile
    entry: FileEntry


@record(slots=False)
class Application:
    """One program, its configuration file, or both."""

    program: SourceFile | None
    configuration: SourceFile | None

    def files(self) -> list[tuple[SourceFile, str]]:
        """Each file with its role, the configuration file first (it runs first)."""
        found = [(self.configuration, "configuration"), (self.program, "program")]
        return [(file, role) for file, role in found if file is not None]

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
        config = self.configuration.text if self.configuration is not None else None
        program = self.program.text if self.program is not None else ""
        try:
            if to == "mintmt":
                result = mintmt.to_mintmt(program, config=config)
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


def read(paths: tuple[Path, ...], config: Path | None) -> list[Application]:
    """The applications the command line names: each program alone, or one with ``config``."""
    try:
        found = collect(paths)
    except FileNotFoundError as error:
        raise UsageError(f"no such file or directory: {error.filename or error.args[0]}") from None
    except OSError as error:  # a link loop, a path under a file, a folder that cannot be read
        raise UsageError(f"cannot read {error.filename}: {error.strerror or error}") from None
    if config is not None:
        if len(found) > 1 or any(is_configuration(path) for path in found):
            raise UsageError("--config pairs one configuration file with one program file")
        itself = program_as_own_configuration(found, config)
        if itself is not None:  # read in both roles; with --write the second write would undo the first
            raise UsageError(f"--config {config} is the program {itself} itself: name the configuration file")
        return [Application(_read(found[0]) if found else None, _read(config))]
    if not found:
        raise UsageError("no .mnt or .cfg files to migrate")
    partners = _partners(found)
    claimed = {_identity(configuration) for configuration in partners.values()}
    return [
        Application(None, _read(path)) if is_configuration(path) else Application(_read(path), _paired(partners, path))
        for path in found
        if not (is_configuration(path) and _identity(path) in claimed)
    ]


def _paired(partners: dict[Path, Path], program: Path) -> SourceFile | None:
    partner = partners.get(program)
    return _read(partner) if partner is not None else None


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
        if unit is not Unit.PROGRAM or partner is None or _identity(partner) in taken:
            continue
        partners[program] = partner
        taken.add(_identity(partner))
    return partners


def _identity(path: Path) -> object:
    """What names one file however it is spelt or linked (its device and inode); where it would be, if missing.

    One stat per file keeps pairing a folder of many programs linear, where comparing each pair was not."""
    try:
        status = path.stat()
    except OSError:
        return path.resolve()
    return status.st_dev, status.st_ino


def _read(path: Path) -> SourceFile:
    try:
        file = read_source(path)
    except OSError as error:
        raise UsageError(f"cannot read {path}: {error.strerror or error}") from None
    binary = file.binary()
    if binary is not None:
        raise UsageError(f"{binary}: nothing migrated")
    return file
