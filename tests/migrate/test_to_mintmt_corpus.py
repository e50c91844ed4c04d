"""Every v4 program of the corpus and of the conformance cases, migrated to MintMT: it checks clean as
MintMT, runs in the simulator to the same trace as the original, and migrates again to itself.

"Clean" means no finding the v4 original does not already have (counted by code: the marker lines
move the lines), apart from findings on a line the migration left for a person. "The same trace" is
``mintlang.migrate.mintmt.verification.verify`` with the drives enabled, over 300 simulated ms: the
terminal, the outputs, the relay and every axis compared at every millisecond. A comparison can be
incomplete only for a reason outside the migration (the original does not compile or stops on an error at
once, as most of the manual's fragments do, the simulator does not model a keyword) or for a line the
migration flagged.
"""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import pytest

import mintlang
from mintlang.diagnostics import LineIndex
from mintlang.migrate.mintmt import to_mintmt
from mintlang.migrate.mintmt.verification import verify
from mintlang.migrate.model import MigrationResult
from mintlang.migrate.verification import Verdict
from mintlang.runtime.scenario import DrivesEnabled, Scenario
from tests.corpus_files import CORPUS

ROOT = CORPUS.parent
DRIVES = Scenario(drives=(DrivesEnabled(),))
UNTIL_MS = 300  # 1000 ms found nothing more on the whole corpus, in twice the time


def _v4_programs() -> list[Path]:
    conformance = ROOT / "conformance"
    cases = (path for path in conformance.rglob("*.mnt") if not {"v3", "mintmt"} & set(path.parts))
    return sorted([*(CORPUS / "v4").rglob("*.mnt"), *cases])


PROGRAMS = _v4_programs()


def _migrated(path: Path) -> tuple[str, str | None, MigrationResult]:
    source = path.read_bytes().decode("utf-8")
    partner = path.with_suffix(".cfg")
    config = partner.read_bytes().decode("utf-8") if partner.exists() else None
    return source, config, to_mintmt(source, config=config)


def _codes(analysis: mintlang.Analysis, text: str, left_for_a_person: set[int]) -> Counter[str]:
    index = LineIndex(text)
    return Counter(
        finding.code for finding in analysis.program if index.position(finding.span.start).line not in left_for_a_person
    )


def test_the_corpus_has_v4_programs_and_configuration_files() -> None:
    assert len(PROGRAMS) > 1000
    assert sum(path.with_suffix(".cfg").exists() for path in PROGRAMS) >= 10


@pytest.mark.parametrize("path", PROGRAMS, ids=lambda path: str(path.relative_to(ROOT)))
def test_migration_checks_clean_as_mintmt_and_runs_to_the_same_trace(path: Path) -> None:
    source, config, result = _migrated(path)
    assert not result.already_mintmt
    flagged = {item.line for item in result.manual}
    original = mintlang.check_application(source, config=config)
    migrated_config = result.configuration.text if result.configuration is not None else None
    migrated = mintlang.check_application(result.text, dialect="mintmt", config=migrated_config)
    new = _codes(migrated, result.text, flagged) - _codes(original, source, set())
    assert not new, [str(finding) for finding in migrated.program if finding.code in new]

    found = verify(result, scenario=DRIVES, until_ms=UNTIL_MS)
    assert found.verdict is not Verdict.DIVERGES, found.divergence
    if found.verdict is Verdict.INCOMPLETE:
        assert found.short is not None
        outside = (
            "the v4 original does not compile",
            "is not simulated by mint-run",
            "left for a person",
            "both runs stopped on an error at 0 ms",  # the original fails at once too: a fragment, a bad value
        )
        assert any(reason in found.short for reason in outside), found.short


@pytest.mark.parametrize("path", PROGRAMS[::7], ids=lambda path: str(path.relative_to(ROOT)))
def test_migrating_the_migration_changes_nothing(path: Path) -> None:
    _, _, result = _migrated(path)
    migrated_config = result.configuration.text if result.configuration is not None else None
    again = to_mintmt(result.text, config=migrated_config)
    assert again.text == result.text
    assert (again.configuration.text if again.configuration else None) == migrated_config
    assert again.changes == ()


def test_most_programs_run_equivalent() -> None:
    """Not every run can be compared to its end, but most must: a verification that came back
    incomplete everywhere would pass the test above and show nothing. A program whose original runs
    past its first instant is compared, and comes out equivalent; the manual's fragments that stop at
    once are most of the rest, so their share moves as cases are added, and only a bound is held."""
    sample = PROGRAMS[::20]
    # ``v3_stop`` is the original's: the MintMT verification reuses the v3 -> v4 one's record
    found = [verify(_migrated(path)[2], scenario=DRIVES, until_ms=UNTIL_MS) for path in sample]
    runs = [
        run
        for run in found
        if not (run.v3_stop is not None and run.v3_stop.reason == "error" and run.v3_stop.time_ms == 0)
    ]
    assert all(run.verdict is Verdict.EQUIVALENT for run in runs), [run.short for run in runs]
    assert len(runs) >= 2 / 3 * len(sample), Counter(run.verdict for run in found)
