"""Every code the checker can emit has an entry in the catalogue and a committed page, and the pages
are what the catalogue gives (``python -m tools.rule_pages`` writes them)."""

from __future__ import annotations

from pathlib import Path

import pytest

from mintlang.ruledocs import find, rules
from mintlang.ruledocs.pages import INDEX, pages
from tests.ruledocs.emitted import emitted_codes

DOCS = Path(__file__).resolve().parents[2] / "docs" / "rules"


def test_the_catalogue_documents_exactly_the_codes_the_checker_emits() -> None:
    documented = {rule.key for rule in rules()}
    assert emitted_codes() - documented == set(), "document these codes in mintlang/ruledocs/catalogue"
    assert documented - emitted_codes() == set(), "these documented codes are never emitted"


def test_no_code_is_documented_twice() -> None:
    codes = [rule.code for rule in rules()]
    assert len(codes) == len(set(codes))


def test_the_committed_pages_are_current() -> None:
    committed = {path.name: path.read_text(encoding="utf-8") for path in DOCS.glob("*.md")}
    expected = pages()
    assert committed.keys() == expected.keys(), "run python -m tools.rule_pages"
    stale = [name for name, text in expected.items() if committed[name] != text]
    assert stale == [], "run python -m tools.rule_pages"


@pytest.mark.parametrize("rule", rules(), ids=lambda rule: rule.code)
def test_every_code_has_a_page_linked_from_the_index(rule) -> None:
    assert (DOCS / f"{rule.code}.md").is_file()
    assert f"]({rule.code}.md)" in (DOCS / INDEX).read_text(encoding="utf-8")


def test_a_code_is_found_in_any_case_and_either_spelling_of_its_number() -> None:
    assert find("e2016") is find("E2016") is not None
    assert find("E2") is find("E0002") is not None and find("E2").key == 2
    assert find("w103").key == "W103"
    assert find("E9999") is None and find("W999") is None and find("X1") is None
