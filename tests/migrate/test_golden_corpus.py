"""Every complete v3 program and configuration file of the v3 guide migrates to the reviewed
v4 text and report stored beside it (see ``golden.py`` for how to regenerate)."""

from __future__ import annotations

import json

import pytest

from tests.migrate.golden import UPDATE, V3_PROGRAMS, Case, cases, write_expected

CASES = cases()


def test_every_corpus_program_has_a_golden_case() -> None:
    stems = {path.stem for path in V3_PROGRAMS.iterdir()}
    assert stems == {case.name for case in CASES}


@pytest.mark.parametrize("case", CASES, ids=lambda case: case.name)
def test_the_input_is_the_corpus_program_as_it_stands(case: Case) -> None:
    """A corrected corpus program (a header note, a misprint) reaches its golden case too."""
    for suffix in (".mnt", ".cfg"):
        source = V3_PROGRAMS / f"{case.name}{suffix}"
        if source.exists():
            assert case.read(f"input{suffix}") == source.read_bytes().decode("utf-8")


@pytest.mark.parametrize("case", CASES, ids=lambda case: case.name)
def test_migration_matches_the_reviewed_output(case: Case) -> None:
    result = case.migrate()
    if UPDATE:
        write_expected(case, result)
    if (case.folder / "input.mnt").exists():
        assert result.text == case.read("expected.mnt")
    if result.configuration is not None:
        assert result.configuration.text == case.read("expected.cfg")
    assert case.report(result) == json.loads(case.read("expected-report.json") or "{}")
