"""The documentation's examples are checked: each "before" reports its code, each "after" does not,
with the severity the page states and fixes exactly as safe as the page says (none, safe, unsafe);
every citation of the guides lands in a numbered section."""

from __future__ import annotations

import pytest

from mintlang.dialect import Dialect
from mintlang.formatting import INDENT_WIDTH, format_text
from mintlang.ruledocs import FixSafety, RuleDoc, rules
from mintlang.ruledocs.render import sections

# A code about a file rather than its text (W120, a file not checked) has no example and cites no guide.
ABOUT_FILES = frozenset({"W120"})
RULES = pytest.mark.parametrize(
    "rule", [rule for rule in rules() if rule.code not in ABOUT_FILES], ids=lambda rule: rule.code
)


def test_only_the_codes_about_files_go_without_an_example_and_a_citation() -> None:
    bare = {rule.code for rule in rules() if rule.example is None or not rule.manual}
    assert bare == ABOUT_FILES


@RULES
def test_the_example_before_reports_the_code(rule: RuleDoc) -> None:
    example = rule.example
    found = example.diagnostics(example.before, (rule.code,))
    assert [d.code for d in found] and {d.code for d in found} == {rule.code}


@RULES
def test_the_example_after_is_clean_of_the_code(rule: RuleDoc) -> None:
    example = rule.example
    assert example.diagnostics(example.after, (rule.code,)) == ()


@RULES
def test_the_example_after_is_written_in_the_house_style(rule: RuleDoc) -> None:
    """What a reader copies passes ``mint format --check``: a subroutine's body at the margin under its label, as
    in the manual's examples (000:1855-1866), and no blanks at a line's end."""
    example = rule.example
    configuration = example.with_program is not None
    assert format_text(example.after, " " * INDENT_WIDTH, Dialect.V4, configuration=configuration) == example.after


@RULES
def test_the_page_states_the_severity_the_checker_reports(rule: RuleDoc) -> None:
    example = rule.example
    assert {d.severity.value for d in example.diagnostics(example.before, (rule.code,))} == {rule.severity}


_SAFETY_OF_FIXES = {FixSafety.SAFE: {True}, FixSafety.UNSAFE: {False}, FixSafety.NONE: set()}


@RULES
def test_the_fixes_offered_are_as_safe_as_the_page_says(rule: RuleDoc) -> None:
    example = rule.example
    fixes = [fix for d in example.diagnostics(example.before, (rule.code,)) for fix in d.fixes]
    assert {fix.safe for fix in fixes} == _SAFETY_OF_FIXES[rule.safety]


@RULES
def test_every_citation_names_a_section_of_a_guide(rule: RuleDoc) -> None:
    found = sections(rule)
    assert found and all("§" in where for where in found)
