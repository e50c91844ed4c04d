"""Every conformance program gives the results worked out by hand from the manual.

Each case runs as written (skipping idle ticks), stepping every tick, and with
every line indented differently; all three must meet every expectation.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

from mintlang.dialect import Dialect
from mintlang.runtime.run import RunResult, run_source
from mintlang.runtime.scenario import expectations_pass
from mintlang.runtime.simulation import Limits
from tests.conformance.cases import CHOICE, CHOICE_DOCUMENTS, CONFORMANCE, Case, all_cases, read_case, reindented
from tests.runtime.running import observable

UNBOUNDED_MS = 600_000  # a case that has not ended after ten simulated minutes is stuck


def _run(case: Case, source: str, *, every_tick: bool) -> RunResult:
    limits = Limits(until_ms=case.until_ms or UNBOUNDED_MS, max_wall_s=60.0, every_tick=every_tick)
    return run_source(
        source,
        config=case.configuration,
        controller=case.controller,
        dialect=case.dialect,
        scenario=case.scenario,
        limits=limits,
        name=case.path.name,
    )


def _verdict(result: RunResult) -> str:
    failed = [
        f"{outcome.expectation.origin}: {outcome.expectation.what} {outcome.expectation.expected}, "
        f"got {outcome.actual} {outcome.detail}"
        for outcome in result.outcomes
        if not outcome.held
    ]
    stop = f"stopped {result.stop.reason.value} at {result.stop.time_ms} ms: {result.stop.message}"
    return "\n".join([stop, *failed])


def _passes(result: RunResult) -> bool:
    return expectations_pass(result.outcomes, result.stop.reason.value)


@pytest.mark.parametrize("path", all_cases(), ids=lambda path: str(path.relative_to(CONFORMANCE).with_suffix("")))
def test_the_case_gives_the_results_of_the_manual(path: Path) -> None:
    case = read_case(path)
    written = _run(case, case.source, every_tick=False)
    assert written.outcomes, "a case must expect something"
    assert _passes(written), _verdict(written)
    stepped = _run(case, case.source, every_tick=True)
    assert observable(stepped) == observable(written), "stepping every tick changed the result"
    moved = _run(case, reindented(case.source), every_tick=False)
    assert _passes(moved), "re-indented:\n" + _verdict(moved)
    assert observable(replace(moved, stop=replace(moved.stop, statement=None))) == observable(
        replace(written, stop=replace(written.stop, statement=None))
    ), "re-indenting the lines changed the result"


def test_there_are_at_least_three_hundred_cases() -> None:
    assert len(all_cases()) >= 300


def test_the_v3_folder_holds_at_least_forty_mint_v3_cases() -> None:
    v3 = [read_case(path) for path in all_cases() if path.is_relative_to(CONFORMANCE / "v3")]
    assert len(v3) >= 40
    assert all(case.dialect is Dialect.V3 for case in v3), "a case under v3/ says REM dialect: v3"
    assert all(any(citation.startswith("001:") for citation in case.citations) for case in v3), "v3 cases cite 001"


def test_every_choice_a_case_rests_on_is_recorded_in_a_choice_document() -> None:
    recorded = {choice for path in CHOICE_DOCUMENTS for choice in CHOICE.findall(path.read_text(encoding="utf-8"))}
    missing = {
        f"{case.name}: {choice}"
        for case in map(read_case, all_cases())
        for choice in case.choices
        if choice not in recorded
    }
    assert not missing
