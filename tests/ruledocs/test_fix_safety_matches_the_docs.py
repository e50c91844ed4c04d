"""Each rule's fixes are as safe as its documentation says: ``--fix`` applies what the page calls safe."""

from __future__ import annotations

import pytest

from mintlang.ruledocs import FixSafety, RuleDoc, rules

FIXED = [rule for rule in rules() if rule.safety is not FixSafety.NONE]


@pytest.mark.parametrize("rule", FIXED, ids=lambda rule: rule.code)
def test_the_examples_fixes_carry_the_documented_safety(rule: RuleDoc) -> None:
    example = rule.example
    fixes = [fix for diagnostic in example.diagnostics(example.before, (rule.code,)) for fix in diagnostic.fixes]
    assert fixes, f"{rule.code}: the documentation names a fix, and its example is offered none"
    assert {fix.safe for fix in fixes} == {rule.safety is FixSafety.SAFE}
