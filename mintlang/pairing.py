"""Which configuration file goes with which program: one rule for the editor, ``mint check`` and ``mint-run``.

A program ``conveyor.mnt`` runs after the configuration file beside it, named
by a pattern (``<name>.cfg`` by default, ``<name>`` standing for the program's
name). Names match without regard to case (``APP.MNT`` with ``app.cfg``), as on
the Windows PCs Mint programs come from; of several names differing only in
case, the one written as the pattern writes it wins. The VS Code extension
asks the language server (its ``mint.applicationFiles`` command) rather than
pairing files itself.
"""

from __future__ import annotations

from collections.abc import Collection
from pathlib import Path

from mintlang.records import record
from mintlang.semantic.units import Unit

DEFAULT_PATTERN = "<name>.cfg"
PROGRAM_SUFFIX = ".mnt"
CONFIGURATION_SUFFIX = ".cfg"  # a file named so is a configuration file, paired or not
_NAME = "<name>"


@record
class Pairing:
    """A pattern split at ``<name>``: the configuration of ``conveyor.mnt`` is ``prefix + "conveyor" + suffix``."""

    prefix: str
    suffix: str

    @classmethod
    def from_pattern(cls, pattern: str) -> Pairing | None:
        """The pairing a pattern describes; None (pairing off) for a pattern without ``<name>``, such as "".

        Raises ValueError for a pattern naming a folder: the configuration file is beside its program.
        """
        if "/" in pattern or "\\" in pattern:
            raise ValueError("the configuration file is beside its program: a name, not a path")
        if _NAME not in pattern:
            return None
        prefix, _, suffix = pattern.partition(_NAME)
        return cls(prefix, suffix)

    def configuration_name(self, program: str) -> str | None:
        """The configuration file name of the program file named ``program``; None for no program's name."""
        if not is_program(program):
            return None
        configuration = self.prefix + program[: -len(PROGRAM_SUFFIX)] + self.suffix
        return None if is_program(configuration) else configuration  # a program is never a configuration

    def program_name(self, configuration: str) -> str | None:
        """The program file name whose configuration file ``configuration`` is; None if the pattern does not fit."""
        if is_program(configuration) or not self.suffix:
            return None
        if not configuration.startswith(self.prefix) or not configuration.lower().endswith(self.suffix.lower()):
            return None
        stem = configuration[len(self.prefix) : len(configuration) - len(self.suffix)]
        return stem + PROGRAM_SUFFIX if stem else None

    def partner_name(self, name: str) -> tuple[Unit, str | None]:
        """Which file of an application the file ``name`` is, and the name of the other file (None: it has none)."""
        if is_program(name):
            return Unit.PROGRAM, self.configuration_name(name)
        program = self.program_name(name)
        return (Unit.PROGRAM, None) if program is None else (Unit.CONFIGURATION, program)


def is_program(name: str) -> bool:
    return name.lower().endswith(PROGRAM_SUFFIX)


def listed_as(name: str, names: Collection[str]) -> str | None:
    """``name`` as ``names`` list it: that very name, else the first equal to it without regard to case."""
    if name in names:
        return name
    lowered = name.lower()
    return next((other for other in names if other.lower() == lowered), None)


_KEPT_FOLDERS = 64
_listings: dict[Path, tuple[int, tuple[str, ...]]] = {}


def names_in(folder: Path) -> tuple[str, ...]:
    """The names of a folder's entries (none when it cannot be listed).

    A folder's names are kept while its modification time stays (adding, removing or
    renaming an entry changes it): a directory of many programs is listed once, not
    once for each, and the editor does not list a network share at every keystroke.
    """
    try:
        stamp = folder.stat().st_mtime_ns
    except OSError:
        return ()
    kept = _listings.get(folder)
    if kept is not None and kept[0] == stamp:
        return kept[1]
    try:
        names = tuple(entry.name for entry in folder.iterdir())
    except OSError:
        return ()
    if len(_listings) >= _KEPT_FOLDERS:
        _listings.clear()
    _listings[folder] = (stamp, names)
    return names


def partner_on_disk(path: Path, pattern: str = DEFAULT_PATTERN) -> tuple[Unit, Path | None]:
    """Which file of an application ``path`` is, and the other file beside it if one exists.

    Raises ValueError for a pattern naming a folder (see ``Pairing.from_pattern``).
    """
    pairing = Pairing.from_pattern(pattern)
    if pairing is None:
        return Unit.PROGRAM, None
    unit, other = pairing.partner_name(path.name)
    if other is None:
        return unit, None
    listed = listed_as(other, names_in(path.parent))
    return unit, None if listed is None else path.parent / listed
