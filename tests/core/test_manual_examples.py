"""Every example of the v4 reference guide gets the diagnostics the guide implies.

Valid examples give no error at all (fragments may name variables and labels
they do not declare: 3001 and 3004 only); invalid ones give exactly the error
numbers the guide names, on the lines their headers say.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang import Severity
from tests.corpus_files import FRAGMENT_ALLOWANCE, CorpusCase, cases


def _errors(case: CorpusCase) -> list[tuple[str, int, str]]:
    analysis = mintlang.check_application(
        case.source, dialect=case.dialect, controller=case.controller, config=case.configuration
    )
    index = mintlang.LineIndex(case.source)
    return [
        (d.code, index.position(d.span.start).line, d.message)
        for d in analysis.program
        if d.severity is Severity.ERROR or (d.code, index.position(d.span.start).line) in case.expected
    ]


def _unexplained(case: CorpusCase, found: list[tuple[str, int, str]]) -> list[tuple[str, int, str]]:
    allowed = FRAGMENT_ALLOWANCE if case.fragment else frozenset()
    expected_codes = {code for code, _ in case.expected}
    return [item for item in found if item[0] not in allowed and item[0] not in expected_codes]


@pytest.mark.parametrize("case", cases("v4/valid"), ids=lambda case: case.name)
def test_valid_example_has_no_error(case: CorpusCase) -> None:
    assert _unexplained(case, _errors(case)) == []


@pytest.mark.parametrize("case", cases("v4/invalid"), ids=lambda case: case.name)
def test_invalid_example_reports_the_manual_error(case: CorpusCase) -> None:
    found = _errors(case)
    reported = {(code, line) for code, line, _ in found}
    assert case.expected, "an invalid example must name the error it expects"
    assert case.expected <= reported, f"missing {sorted(case.expected - reported)}; reported {found}"
    assert _unexplained(case, found) == []
