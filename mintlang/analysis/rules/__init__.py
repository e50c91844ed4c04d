"""The analyser's rules, one module each, in the order they run."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass

from mintlang.analysis.findings import Finding
from mintlang.analysis.rules import (
    addressing,
    arrays,
    collisions,
    declarations,
    events,
    flow,
    hints,
    keyword_usage,
    limits,
    startup,
    unused,
    v3_keywords,
    values,
)
from mintlang.analysis.traversal import Facts
from mintlang.dialect import Dialect


@dataclass(frozen=True, slots=True)
class Rule:
    name: str
    check: Callable[[Facts], Iterator[Finding]]
    dialects: frozenset[Dialect] = frozenset(Dialect)

    @property
    def summary(self) -> str:
        """The first line of the rule module's docstring."""
        module = __import__(self.check.__module__, fromlist=["__doc__"])
        return (module.__doc__ or "").strip().splitlines()[0]


# Rules that read the keywords' v4 attributes; v3 code is only read to be migrated.
_V4_ATTRIBUTES = frozenset({Dialect.V4})

RULES: tuple[Rule, ...] = (
    Rule("declarations", declarations.check),
    Rule("keyword-usage", keyword_usage.check, _V4_ATTRIBUTES),
    Rule("addressing", addressing.check, _V4_ATTRIBUTES),
    Rule("values", values.check, _V4_ATTRIBUTES),
    Rule("arrays", arrays.check),
    Rule("events", events.check),
    Rule("v3-keywords", v3_keywords.check),
    Rule("flow", flow.check),
    Rule("limits", limits.check),
    Rule("startup", startup.check),
    Rule("collisions", collisions.check),
    Rule("unused", unused.check),
    Rule("hints", hints.check, _V4_ATTRIBUTES),
)
