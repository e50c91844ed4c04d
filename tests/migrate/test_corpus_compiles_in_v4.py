"""The migrated corpus passes ``mint check --dialect v4``: every error-severity diagnostic
left sits on a line the migrator flagged as a manual item (the placeholders it leaves on
purpose), and most programs have none at all."""

from __future__ import annotations

import pytest

import mintlang
from mintlang.diagnostics import Severity
from mintlang.migrate import MigrationResult, migrate
from tests.migrate.golden import Case, cases
from tests.migrate.helpers import errors_left_unflagged

CASES = cases()


def _analysis(result: MigrationResult) -> mintlang.Analysis:
    config = result.configuration.text if result.configuration is not None else None
    return mintlang.check_application(result.text, dialect="v4", controller="nextmove-pci", config=config)


@pytest.mark.parametrize("case", CASES, ids=lambda case: case.name)
def test_errors_left_are_all_manual_items(case: Case) -> None:
    assert errors_left_unflagged(case.migrate(), "nextmove-pci") == []


@pytest.mark.parametrize("controller", ["mintdrive", "servonode51"])
def test_errors_left_on_a_one_axis_controller_are_all_manual_items(controller: str) -> None:
    """The corpus moves two and three axes: on a one-axis target those lines are flagged (X-CHECK)."""
    for case in CASES:
        result = migrate(case.read("input.mnt") or "", config=case.read("input.cfg"), controller=controller)
        assert errors_left_unflagged(result, controller) == [], case.name


def test_most_of_the_corpus_migrates_without_any_v4_error() -> None:
    clean = 0
    for case in CASES:
        analysis = _analysis(case.migrate())
        diagnostics = [*analysis.program, *(analysis.configuration or ())]
        clean += not any(d.severity is Severity.ERROR for d in diagnostics)
    assert clean >= 33, f"only {clean} of {len(CASES)} migrate to zero v4 errors"
