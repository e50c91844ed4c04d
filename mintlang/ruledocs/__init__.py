"""The documentation of every code the checker reports, in one place.

``catalogue`` holds what each code catches, why it matters, an example before and
after (tests check both with the checker), the guides' sections and its fix.
``mint rule`` shows it, ``python -m tools.rule_pages`` writes it to ``docs/rules/``,
and each diagnostic links to its page (``links``).
"""

from __future__ import annotations

from functools import cache

from mintlang.codes import code_named
from mintlang.ruledocs.catalogue import GROUPS
from mintlang.ruledocs.model import Example, FixSafety, Group, RuleDoc

__all__ = ["GROUPS", "Example", "FixSafety", "Group", "RuleDoc", "find", "group_of", "rules"]


def rules() -> tuple[RuleDoc, ...]:
    """Every documented code, group by group."""
    return tuple(rule for group in GROUPS for rule in group.rules)


@cache
def _by_code() -> dict[str, RuleDoc]:
    return {rule.code: rule for rule in rules()}


def find(code: str) -> RuleDoc | None:
    """The documentation of ``code`` as a user writes it: any case, and the controller's numbers in
    either spelling (``E2``, ``E0002``)."""
    named = code_named(code)
    return _by_code().get(named) if named is not None else None


def group_of(rule: RuleDoc) -> Group:
    return next(group for group in GROUPS if rule in group.rules)
