"""Which configuration file each file of a ``mint check`` run is checked with, and under which settings.

Each file has the settings of its nearest settings file, under the command
line's (``mintlang.settings``). A program sees ``--config`` if given, else the
``config`` of its settings file, else the configuration file paired with it
(``mintlang.pairing``, the rule the editor follows), unless ``--no-config``. A
configuration file is reported once, as its programs see it (a name is unused
only if none of them uses it); named on its own (``mint check cell.cfg``) it is
checked with its paired program as the editor checks it, without reporting the
program.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Mapping, Sequence
from dataclasses import field
from pathlib import Path

from mintlang import check_application
from mintlang.analysis.suppression import UNUSED_SUPPRESSION
from mintlang.cli.checking import Checked, CheckOptions, FileFixed, Job
from mintlang.cli.files import Unchecked, is_configuration, not_text, unread
from mintlang.cli.report import FileReport
from mintlang.cli.settings import whole_settings
from mintlang.diagnostics import Diagnostic
from mintlang.fixes import Fixed
from mintlang.records import record
from mintlang.semantic.units import Unit
from mintlang.settings import FileSettings, Overrides, settings_for
from mintlang.source import SourceFile, read_source

# Unused variable, macro, suppression: a use in any program counts.
_USE_FINDINGS = frozenset({"W103", "W105", UNUSED_SUPPRESSION})


def options_of(settings: FileSettings) -> CheckOptions:
    dialect = settings.dialect
    return CheckOptions(dialect.value, settings.controller.value, settings.selected, settings.ignored, dialect.chosen)


@record(frozen=False, slots=False)
class _Configuration:
    """One configuration file of the run, the jobs of the programs that see it, and where its report goes."""

    source: SourceFile
    options: CheckOptions
    jobs: list[int] = field(default_factory=list)
    place: int = 0  # the index of the first job whose report follows it

    def job(self, program: Path, options: CheckOptions, source: SourceFile | None = None) -> Job:
        """The check of ``program`` with this file, whose findings its own settings' ``ignore`` and
        ``per-file-ignores`` leave out, not the program's."""
        return Job(program, options, self.source.text, source, configuration_ignore=self.options.ignore)


@record(frozen=False, slots=False)
class Plan:
    """The jobs of a run, the configuration files their programs see, and the problems found planning them."""

    overrides: Overrides  # the command line's settings, for each configuration file's own
    jobs: list[Job] = field(default_factory=list)
    problems: list[Unchecked] = field(default_factory=list)
    hidden: set[int] = field(default_factory=set)  # jobs run for a configuration named alone: their report is not
    _configurations: dict[Path, _Configuration] = field(default_factory=dict)
    _failed: set[Path] = field(default_factory=set)

    def add(self, path: Path, settings: FileSettings, source: SourceFile | None = None) -> None:
        """Plan the file ``path`` (``source``: its text, for standard input)."""
        unit, other = settings.partner(path)
        if unit is Unit.CONFIGURATION:
            self._add_configuration(path, settings, program=other, source=source)
            return
        configuration = self._configuration(other) if other is not None else None
        if other is not None and configuration is None:
            reason = f"not checked, as its configuration file {other} could not be read"
            self.problems.append(Unchecked(str(path), reason, f"{path}: {reason}"))
            return
        if configuration is None:
            self.jobs.append(Job(path, options_of(settings), source=source))
            return
        configuration.jobs.append(len(self.jobs))
        self.jobs.append(configuration.job(path, options_of(settings), source))

    @property
    def empty(self) -> bool:
        """Nothing to check or report: no program, no configuration file."""
        return not self.jobs and not self._configurations

    def configured(self, path: Path) -> bool:
        """Whether ``path`` is the configuration file of a program already planned."""
        key = _key(path)
        return key in self._configurations and bool(self._configurations[key].jobs)

    def _add_configuration(
        self, path: Path, settings: FileSettings, program: Path | None, source: SourceFile | None = None
    ) -> None:
        if self.configured(path):
            return  # reported with its programs
        configuration = self._configuration(path, source)
        if configuration is None:
            return
        configuration.place = len(self.jobs)
        if program is not None:  # checked as the editor checks it: with its program, which is not reported
            self.hidden.add(len(self.jobs))
            configuration.jobs.append(len(self.jobs))
            self.jobs.append(configuration.job(program, options_of(settings)))

    def _configuration(self, path: Path, source: SourceFile | None = None) -> _Configuration | None:
        """The configuration file ``path``, read once for the run (``source``: the text standard input gave under its
        name, not the file on disk); None (and a problem) if it cannot be read."""
        key = _key(path)
        if key in self._failed:
            return None
        if key not in self._configurations:
            try:
                source = source if source is not None else read_source(path)
            except OSError as error:
                return self._fail(key, unread(error))
            if (binary := not_text(source)) is not None:
                return self._fail(key, binary)
            options = options_of(settings_for(path, self.overrides))
            self._configurations[key] = _Configuration(source, options, place=len(self.jobs))
        return self._configurations[key]

    def _fail(self, key: Path, problem: Unchecked) -> None:
        self._failed.add(key)
        self.problems.append(problem)

    def reports(self, results: Sequence[Checked], configurations: Mapping[Path, FileReport]) -> list[FileReport]:
        """The reports in the order the files were planned, each configuration's (from ``configurations``, by the
        file's key: ``configuration_reports``, or what ``--add-ignore`` left) before its first program's."""
        placed: dict[int, list[FileReport]] = {}
        for key, configuration in self._configurations.items():
            placed.setdefault(configuration.place, []).append(configurations[key])
        reports: list[FileReport] = []
        for index, result in enumerate(results):
            reports.extend(placed.pop(index, []))
            if result.report is not None and index not in self.hidden:
                reports.append(result.report)
        reports.extend(report for rest in placed.values() for report in rest)
        return reports

    def configuration_reports(self, results: Sequence[Checked]) -> dict[Path, FileReport]:
        """Each configuration file's report, by its key: as its programs saw it, or checked on its own."""
        return {
            key: _configuration_report(
                configuration, [results[i].configuration for i in configuration.jobs if results[i].report is not None]
            )
            for key, configuration in self._configurations.items()
        }

    def silenced_configurations(self, reports: Mapping[Path, FileReport]) -> dict[Path, FileFixed]:
        """``--add-ignore`` for the configuration files: each one's findings (``reports``, by the file's key)
        silenced by comments on their lines (not a MintMT file read as v4, whose comments are not REM)."""
        from mintlang.analysis.silencing import silence  # noqa: PLC0415 - --add-ignore alone needs it

        silenced = {}
        for key, configuration in self._configurations.items():
            source, options, found = configuration.source, configuration.options, reports[key].diagnostics
            if not found or options.hint(source) is not None:
                continue
            analysis = check_application("", config=source.text, dialect=options.dialect, controller=options.controller)
            done = silence(analysis.model, found, Unit.CONFIGURATION)
            silenced[key] = FileFixed(source, Fixed(done.text, done.silenced, done.left, converged=True))
        return silenced

    def program_reports(self, results: Sequence[Checked]) -> list[FileReport]:
        """The reports of the programs alone: what ``--fix`` fixes, as it leaves configuration files as they are,
        and a program that looks like MintMT but is read as v4 (``Checked.hint``)."""
        return [
            r.report for i, r in enumerate(results) if r.report is not None and r.hint is None and i not in self.hidden
        ]


def _key(path: Path) -> Path:
    """One key for the names of one file (``cell.cfg`` named and found as ``CELL.CFG`` through a link)."""
    try:
        return path.resolve(strict=True)
    except OSError:
        return path.absolute()


def plan(files: Sequence[Path], overrides: Overrides, stdin: SourceFile | None = None) -> Plan:
    """The jobs of a run: standard input's program first, then the programs, then the configuration files named
    on their own. Raises SettingsError for a settings file that cannot be used."""
    planned = Plan(overrides)
    if stdin is not None:
        planned.add(stdin.path, whole_settings(stdin.path, overrides), stdin)
    for path in files:
        if not is_configuration(path):
            planned.add(path, whole_settings(path, overrides))
    for path in files:
        if is_configuration(path):
            planned.add(path, whole_settings(path, overrides))
    return planned


def _configuration_with_programs(seen_by_programs: list[tuple[Diagnostic, ...]]) -> tuple[Diagnostic, ...]:
    """The configuration's findings, each once; a name is unused only if no program uses it."""
    counts: Counter[Diagnostic] = Counter(d for diagnostics in seen_by_programs for d in dict.fromkeys(diagnostics))
    kept = [d for d, count in counts.items() if d.code not in _USE_FINDINGS or count == len(seen_by_programs)]
    return tuple(sorted(kept, key=lambda d: (d.span.start, d.span.end, d.code)))


def _configuration_report(configuration: _Configuration, seen_by_programs: list[tuple[Diagnostic, ...]]) -> FileReport:
    """A configuration file's findings: as its programs saw it, or checked on its own (with an empty program)."""
    source, options = configuration.source, configuration.options
    if seen_by_programs:
        return FileReport(str(source.path), source.text, _configuration_with_programs(seen_by_programs))
    analysis = check_application(
        "",
        config=source.text,
        dialect=options.dialect,
        controller=options.controller,
        select=options.select,
        ignore=options.ignore,
    )
    return FileReport(str(source.path), source.text, analysis.configuration)
