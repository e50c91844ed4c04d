"""Which files are tests: programs with ``REM @expect`` lines or a scenario file beside them.

A program whose configuration file alone has them is a test too: they are not read from there, and its run
says so (``ignored_directives``) rather than the program dropping out of the run without a word.
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

from mintlang.cli.files import find, walk
from mintlang.pairing import listed_as, names_in
from mintlang.records import record
from mintlang.runtime.scenario.directive_words import DIRECTIVE, meant_kind
from mintlang.semantic.units import Unit
from mintlang.settings import FileSettings, Overrides, SettingsError, settings_for
from mintlang.source import read_source

SCENARIO_SUFFIX = ".scenario.toml"


@record
class TestCase:
    """One program to run, with the scenario file beside it if it has one."""

    program: Path
    scenario: Path | None

    @property
    def name(self) -> str:
        return str(self.program)


@record
class Unreadable:
    """A path given or found that could not be read, or a scenario file that runs nothing: reported, and the
    run goes on.

    ``message`` names the path, and the line and column when the reason lies at a place in the file
    (``blob.mnt:2:1: not Mint text (a NUL byte)``, as ``mint check`` and ``mint-run`` say it).
    """

    message: str

    @classmethod
    def at(cls, path: Path, reason: str) -> Unreadable:
        return cls(f"{path}: {reason}")


def discover(paths: Iterable[Path], overrides: Overrides | None = None) -> tuple[list[TestCase], list[Unreadable]]:
    """The tests under ``paths`` (files or folders, searched recursively as ``mint check`` searches them, less
    what the settings under ``overrides`` exclude), in path order, each once."""
    paths = list(paths)
    found = find(paths, overrides=overrides)
    problems = [Unreadable.at(Path(error.filename), _reason(error)) for error in found.unreadable]
    # each scenario file with no program once, by the file it is: named and below a folder named, or in two spellings
    orphans = {orphan.resolve(): orphan for orphan in reversed(_scenarios_without_program(paths, overrides))}
    cases: dict[Path, TestCase] = {}
    for named in found.files:
        program = _program_of(named, orphans)
        case = _case(program, problems, overrides) if program is not None else None
        if case is not None:
            cases.setdefault(program.resolve(), case)
    problems += sorted((_orphan(orphan) for orphan in orphans.values()), key=lambda orphan: orphan.message)
    return sorted(cases.values(), key=lambda case: str(case.program)), problems


def _scenarios_without_program(paths: Iterable[Path], overrides: Overrides | None) -> list[Path]:
    """Scenario files below the folders with no program of their name beside them: a misnamed program or
    scenario would otherwise leave its test unrun without a word (folders that cannot be listed ``find``
    reports; what the settings exclude ``find`` leaves out, and so does this)."""
    orphans = []
    for directory in (path for path in paths if path.is_dir()):
        for folder, names in walk(directory, lambda name: name.lower().endswith(SCENARIO_SUFFIX), overrides):
            listing = names_in(Path(folder))
            orphans += [Path(folder, name) for name in names if listed_as(_program_name(name), listing) is None]
    return orphans


def _program_of(path: Path, orphans: dict[Path, Path]) -> Path | None:
    """The program a file named or found stands for: itself, or for a scenario file named on the command line,
    the program beside it whose test the file holds (None, and the file among ``orphans``, when there is none)."""
    if not path.name.lower().endswith(SCENARIO_SUFFIX):
        return path
    name = listed_as(_program_name(path.name), names_in(path.parent))
    if name is None:
        orphans.setdefault(path.resolve(), path)
        return None
    return path.parent / name


def _program_name(scenario_name: str) -> str:
    return scenario_name[: -len(SCENARIO_SUFFIX)] + ".mnt"


def _orphan(scenario: Path) -> Unreadable:
    """A scenario file with no program of its name beside it."""
    return Unreadable.at(scenario, f"no program {_program_name(scenario.name)} beside it, so it runs nothing")


def _reason(error: OSError) -> str:
    """Why a path ``find`` met could not be looked at, in a few words."""
    if isinstance(error, FileNotFoundError):
        return "a link to nothing" if Path(error.filename).is_symlink() else "no such file or folder"
    return error.strerror or str(error)


def _case(program: Path, problems: list[Unreadable], overrides: Overrides | None) -> TestCase | None:
    scenario_name = listed_as(program.stem + SCENARIO_SUFFIX, names_in(program.parent))
    if scenario_name is not None:
        return TestCase(program, program.parent / scenario_name)
    try:
        source = read_source(program)  # refuses a FIFO or a device, which would block or never end
    except OSError as error:
        problems.append(Unreadable.at(program, error.strerror or str(error)))
        return None
    if (binary := source.binary()) is not None:
        problems.append(Unreadable(binary))
        return None
    with_expectations = _expects(source.text) or _expects_in_configuration(program, overrides)
    return TestCase(program, None) if with_expectations else None


def configuration_of(program: Path, settings: FileSettings) -> Path | None:
    """The configuration file that runs before ``program``; none for a configuration file run as a test."""
    unit, partner = settings.partner(program)
    return partner if unit is Unit.PROGRAM else None


def _expects_in_configuration(program: Path, overrides: Overrides | None) -> bool:
    """Whether the configuration file of ``program`` has an ``@expect`` line; a settings or configuration file
    that cannot be read is not looked into here (the run of a test reports it)."""
    try:
        configuration = configuration_of(program, settings_for(program, overrides))
        return configuration is not None and _expects(read_source(configuration).text)
    except (OSError, SettingsError, ValueError):
        return False


def _expects(text: str) -> bool:
    """Whether ``text`` has an ``@expect`` line, or one meant to be (its run then reports the misspelling)."""
    return any(meant_kind(found["word"]) == "expect" for found in DIRECTIVE.finditer(text))
