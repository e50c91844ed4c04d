"""The v4 conformance cases migrated to MintMT still give the results worked out by hand from the manual.

A case's ``REM @expect`` lines become ``' @expect`` lines, which ``mint-run`` reads in MintMT too, so the
migration of a case is run as MintMT (same controller, scenario and configuration file) and must meet the
case's own expectations: variables, ``ERR``, what is printed, how the run ends. That checks more than the
trace comparison of ``test_to_mintmt_corpus``, which sees the terminal, outputs and axes but no variable.
A case the migration flags a line of runs without its ``REM MIGRATE:`` lines: they are comments, but each
moves the lines below it, and an expected ``ERL`` with them. A case whose v4 program does not compile must
not compile as MintMT either (its expectations about the refusal are v4's), unless the migration flags the
line that MintMT reads otherwise: then the case's expectations are v4's refusal, which MintMT does not share.
"""

from __future__ import annotations

import functools
from pathlib import Path

import pytest

from mintlang.dialect import Dialect
from mintlang.migrate import MigrationResult
from mintlang.migrate.context import MARKER
from mintlang.migrate.mintmt import to_mintmt
from mintlang.runtime.run import RunResult, run_source
from mintlang.runtime.scenario import expectations_pass
from mintlang.runtime.simulation import Limits
from tests.conformance.cases import CONFORMANCE, Case, MalformedCase, all_cases, read_case
from tests.conformance.test_conformance import UNBOUNDED_MS, _verdict


def _run(case: Case, source: str, config: str | None, dialect: Dialect) -> RunResult:
    limits = Limits(until_ms=case.until_ms or UNBOUNDED_MS, max_wall_s=60.0)
    return run_source(
        source,
        config=config,
        controller=case.controller,
        dialect=dialect,
        scenario=case.scenario,
        limits=limits,
        name=case.path.name,
    )


def _v4_cases() -> list[Path]:
    found = []
    for path in all_cases():
        try:
            case = read_case(path)
        except MalformedCase:
            continue  # test_conformance reports it
        if case.dialect is Dialect.V4:
            found.append(path)
    return found


CASES = _v4_cases()


@functools.cache  # migrated when a test asks, not while the tests are collected (by every worker)
def _migrated(path: Path) -> tuple[Case, MigrationResult]:
    case = read_case(path)
    return case, to_mintmt(case.source, config=case.configuration)


def test_most_v4_cases_are_migrated_without_a_flag() -> None:
    unflagged = [path for path in CASES if not _migrated(path)[1].manual]
    assert len(unflagged) > 400  # of about 600


def _without_markers(text: str) -> str:
    """``text`` without the migration's marker lines, so that every other line keeps its number."""
    return "".join(line for line in text.splitlines(keepends=True) if not line.lstrip().startswith(MARKER))


@pytest.mark.parametrize("path", CASES, ids=lambda path: str(path.relative_to(CONFORMANCE).with_suffix("")))
def test_the_migrated_case_gives_the_results_of_the_manual(path: Path) -> None:
    case, result = _migrated(path)
    configuration = _without_markers(result.configuration.text) if result.configuration is not None else None
    migrated = _run(case, _without_markers(result.text), configuration, Dialect.MINTMT)
    if migrated.refused:
        assert _refused_in_v4(case), _verdict(migrated)
        return
    assert migrated.outcomes, "the case's expectations are read in MintMT"
    if expectations_pass(migrated.outcomes, migrated.stop.reason.value):
        return
    # the one divergence allowed: a flagged line MintMT compiles where v4 refused the program
    assert result.manual and _refused_in_v4(case), _verdict(migrated)


def _refused_in_v4(case: Case) -> bool:
    return _run(case, case.source, case.configuration, Dialect.V4).refused


def test_a_comms_handler_made_an_event_runs_when_the_host_writes() -> None:
    """The case ``#COMMS1`` … ``RETURN`` (v4 guide 8.10) becomes ``Event Comms1`` … ``End Event`` (002:79-85),
    which the host's write calls just the same: the case's ``v = 42`` and ``n = 1`` hold."""
    path = CONFORMANCE / "events" / "comms_event_on_host_write.mnt"
    case = read_case(path)
    result = to_mintmt(case.source)
    assert "EVENT COMMS1\n" in result.text and "END EVENT\n" in result.text
    migrated = _run(case, result.text, None, Dialect.MINTMT)
    assert expectations_pass(migrated.outcomes, migrated.stop.reason.value), _verdict(migrated)
