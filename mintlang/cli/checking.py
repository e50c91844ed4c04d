"""Checking one file: the unit of work ``mint check`` hands to its worker processes.

A job carries everything its check needs (the path, the configuration's text,
the options), so a worker process needs nothing else from the command; what
comes back is a report, or the one line saying why the file was not checked.
"""

from __future__ import annotations

from dataclasses import field, replace
from enum import StrEnum
from pathlib import Path
from typing import TYPE_CHECKING

from mintlang import check_application
from mintlang.allocation import kept_without_collector
from mintlang.cli.files import Unchecked, is_configuration, not_text, unread
from mintlang.cli.report import FileReport
from mintlang.codes import DEFAULT_SELECT, SYNTAX_ERRORS
from mintlang.detection import dialect_hint
from mintlang.diagnostics import Diagnostic
from mintlang.dialect import Dialect
from mintlang.fixes import Fixed, automatic_fix, fix_text, left_out
from mintlang.records import record
from mintlang.source import SourceFile, read_source

if TYPE_CHECKING:
    from collections.abc import Callable, Sequence

    from mintlang.analysis.analyser import Analysis


@record
class CheckOptions:
    """What ``check_application`` is asked besides the text."""

    dialect: str
    controller: str
    select: tuple[str, ...] | None
    ignore: tuple[str, ...]
    dialect_chosen: bool  # False: v4 by default, so a program that looks like MintMT gets a hint

    def hint(self, source: SourceFile) -> str | None:
        """What to say of a file that looks like MintMT but is read as v4 by default; None if nothing."""
        return None if self.dialect_chosen else dialect_hint(str(source.path), source.text, Dialect(self.dialect))


class Fixing(StrEnum):
    """Which fixes a run applies; ``SILENCE``: none, each finding silenced by a comment instead (--add-ignore)."""

    SAFE = "safe"
    UNSAFE = "unsafe"
    SILENCE = "silence"

    @classmethod
    def asked(cls, fix: bool, unsafe_fixes: bool, diff: bool, *, add_ignore: bool = False) -> Fixing | None:
        """What ``--fix``, ``--unsafe-fixes``, ``--diff`` and ``--add-ignore`` ask; None: report only."""
        if add_ignore:
            return cls.SILENCE
        if not (fix or diff):
            return None
        return cls.UNSAFE if unsafe_fixes else cls.SAFE


@record
class Job:
    """A file to check; ``source`` is given for standard input, which a worker cannot read."""

    path: Path
    options: CheckOptions
    configuration: str | None = None  # the text of the configuration file the program sees
    source: SourceFile | None = None
    configuration_ignore: tuple[str, ...] | None = None  # the configuration file's own; None: the program's
    fixing: Fixing | None = None  # fix the program (--fix), and with which fixes


@record
class FileFixed:
    """A program as read, and as fixed (``fixed.text``)."""

    original: SourceFile
    fixed: Fixed

    @property
    def changed(self) -> bool:
        return self.fixed.text != self.original.text


@record
class Checked:
    """A file's report and the configuration's findings as this program sees it; or why it was not checked."""

    report: FileReport | None
    configuration: tuple[Diagnostic, ...] = field(default=())
    problem: Unchecked | None = None
    fixed: FileFixed | None = None  # the program as read and as fixed, when fixing
    as_read: FileReport | None = None  # when fixing: the report of the text as read, for a fix not written
    hint: str | None = None  # the program looks like MintMT, read as v4 by default (``dialect_hint``)

    def unfixed(self) -> Checked:
        """This check as if nothing had been fixed: the fixed text could not be written."""
        return replace(self, report=self.as_read, fixed=None, as_read=None) if self.as_read is not None else self


# What a check leaves alive (the modules it imported, the parser's tables, the keyword database, the caches) is
# kept for the next file: left in the collector's youngest generation, the first collection after the check
# walked all of it, a thirtieth of a one-line check.
@kept_without_collector
def check_file(job: Job) -> Checked:
    """Read and check one file; an unreadable or binary file is a problem, not an exception."""
    try:
        source = job.source or read_source(job.path)
    except OSError as error:
        return Checked(None, problem=unread(error))
    if (binary := not_text(source)) is not None:
        return Checked(None, problem=binary)
    options = job.options
    arguments = {
        "dialect": options.dialect,
        "controller": options.controller,
        "ignore": options.ignore,
        "config_ignore": job.configuration_ignore,
    }
    if is_configuration(job.path):
        analysis = check_application("", config=source.text, select=options.select, **arguments)
        return Checked(FileReport(str(source.path), source.text, analysis.configuration))
    hint = options.hint(source)
    if job.fixing is not None and hint is None:  # a MintMT program read as v4 is not written as v4: the hint says why
        return (_silence_program if job.fixing is Fixing.SILENCE else _fix_program)(job, source, arguments)
    analysis = _analyser(job, arguments)(source.text)
    found = analysis.program
    unfixed: dict[tuple[str, str], str] = {}
    if hint is None and any(automatic_fix(diagnostic, unsafe=True) is not None for diagnostic in found):
        seen = _FixingCheck(job, arguments, [])
        unfixed = left_out(source.text, seen(source.text) if seen.wider else found, seen)
    report = FileReport(str(source.path), source.text, found, left_out=tuple(unfixed.items()))
    return Checked(report, analysis.configuration, hint=hint)


def _analyser(job: Job, arguments: dict[str, object]) -> Callable[[str], Analysis]:
    """The check of a text of the job's program, with its configuration file."""
    return lambda text: check_application(text, config=job.configuration, select=job.options.select, **arguments)


_SYNTAX_CODES = tuple(f"E{number}" for number in sorted(SYNTAX_ERRORS))


@record
class _FixingCheck:
    """The findings the rounds of fixes see in a text: those selected, and every syntax error, selected or not,
    without its fixes, so that no fix writes one a narrower selection hides (``--select E3007`` hid the 2006 of
    'the' respelt THEN, and --fix wrote it). ``reported`` keeps the selected ones of them."""

    job: Job
    arguments: dict[str, object]
    analyses: list[Analysis]  # each check made, in order

    @property
    def wider(self) -> bool:
        """Whether the selection leaves out a syntax error, so that the rounds' checks select more."""
        return not all(map(self._selected_code, _SYNTAX_CODES))

    def __call__(self, text: str) -> tuple[Diagnostic, ...]:
        options = self.job.options
        if not self.wider:
            self.analyses.append(_analyser(self.job, self.arguments)(text))
            return self.analyses[-1].program
        ignore = tuple(prefix for prefix in options.ignore if not any(c.startswith(prefix) for c in _SYNTAX_CODES))
        select = (*(DEFAULT_SELECT if options.select is None else options.select), *_SYNTAX_CODES)
        arguments = {**self.arguments, "ignore": ignore}
        self.analyses.append(check_application(text, config=self.job.configuration, select=select, **arguments))
        return tuple(
            diagnostic if self._selected(diagnostic) else replace(diagnostic, fixes=())
            for diagnostic in self.analyses[-1].program
            if self._selected(diagnostic) or diagnostic.mint_error in SYNTAX_ERRORS
        )

    def _selected(self, diagnostic: Diagnostic) -> bool:
        return self._selected_code(diagnostic.code)

    def _selected_code(self, code: str) -> bool:
        from mintlang.analysis.analyser import code_selected  # noqa: PLC0415 - as check_application imports it

        return code_selected(code, self.job.options.select, self.job.options.ignore)

    def reported(self, found: Sequence[Diagnostic]) -> tuple[Diagnostic, ...]:
        return tuple(filter(self._selected, found)) if self.wider else tuple(found)


def _fix_program(job: Job, source: SourceFile, arguments: dict[str, object]) -> Checked:
    """Fix the program round after round; its report is that of the fixed text."""
    analyses: list[Analysis] = []
    seen = _FixingCheck(job, arguments, analyses)
    fixed = fix_text(source.text, seen, unsafe=job.fixing is Fixing.UNSAFE)
    # what is left to --unsafe-fixes after the safe fixes, or to a second --fix, is counted as the report's is
    unfixed = left_out(fixed.text, fixed.remaining, seen, dict(fixed.left_out))
    fixed = replace(fixed, remaining=seen.reported(fixed.remaining))
    report = FileReport(str(source.path), fixed.text, fixed.remaining, left_out=tuple(unfixed.items()))
    as_read = FileReport(str(source.path), source.text, seen.reported(analyses[0].program))
    return Checked(report, analyses[-1].configuration, fixed=FileFixed(source, fixed), as_read=as_read)


def _silence_program(job: Job, source: SourceFile, arguments: dict[str, object]) -> Checked:
    """Silence each finding of the program with a comment on its line; its report is what the new text has."""
    from mintlang.analysis.silencing import silence  # noqa: PLC0415 - --add-ignore alone needs it

    analysed = _analyser(job, arguments)
    before = analysed(source.text)
    silenced = silence(before.model, before.program)
    after = analysed(silenced.text)
    fixed = Fixed(silenced.text, silenced.silenced, tuple(after.program), converged=True)
    report = FileReport(str(source.path), silenced.text, fixed.remaining)
    as_read = FileReport(str(source.path), source.text, before.program)
    return Checked(report, after.configuration, fixed=FileFixed(source, fixed), as_read=as_read)
