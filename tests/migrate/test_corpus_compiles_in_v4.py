"""The migrated corpus passes ``mint check --dialect v4``: every error-severity diagnostic
left sits on a line the migrator flagged as a manual item (the placeholders it leaves on
purpose), and most programs have none at all."""

from __future__ import annotations

import pytest

import mintlang
from mintlang.diagnostics import LineIndex, Severity
from mintlang.migrate import MigrationResult
from tests.migrate.golden import Case, cases

CASES = cases()


def _unflagged_errors(result: MigrationResult, diagnostics: tuple[mintlang.Diagnostic, ...]) -> list[str]:
    flagged = {item.line for item in result.manual}
    index = LineIndex(result.text)
    return [
        f"{index.position(d.span.start).line}: {d.code} {d.message}"
        for d in diagnostics
        if d.severity is Severity.ERROR and index.position(d.span.start).line not in flagged
    ]


def _analysis(result: MigrationResult) -> mintlang.Analysis:
    config = result.configuration.text if result.configuration is not None else None
    return mintlang.check_application(result.text, dialect="v4", controller="nextmove-pci", config=config)


@pytest.mark.parametrize("case", CASES, ids=lambda case: case.name)
def test_errors_left_are_all_manual_items(case: Case) -> None:
    result = case.migrate()
    analysis = _analysis(result)
    assert _unflagged_errors(result, tuple(analysis.program)) == []
    if result.configuration is not None:
        assert _unflagged_errors(result.configuration, tuple(analysis.configuration or ())) == []


def test_most_of_the_corpus_migrates_without_any_v4_error() -> None:
    clean = 0
    for case in CASES:
        analysis = _analysis(case.migrate())
        diagnostics = [*analysis.program, *(analysis.configuration or ())]
        clean += not any(d.severity is Severity.ERROR for d in diagnostics)
    assert clean >= 33, f"only {clean} of {len(CASES)} migrate to zero v4 errors"
