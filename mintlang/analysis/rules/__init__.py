"""The analyser's rules, one module each, in the order they run.

A rule reads the whole application (``check``), or one line at a time
(``each_line``: what it finds depends on nothing outside the line, so the
analyser keeps it while the line is unchanged), or both; or each physical line
of the text as it is written (``each_text_line``), comments included. A rule
that reads the whole application may say what it reads of a line (``reads``):
after an edit that leaves that the same, what it found is carried over. A line
rule may say what of a line it looks at (``looks_at``): it is skipped on the
lines that have none of it. The memory estimate (``memory``) reads the files'
lengths: the analyser checks it on every version.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

from mintlang.analysis.findings import Finding
from mintlang.analysis.rules import (
    addressing,
    arrays,
    calls,
    collisions,
    declarations,
    empty_values,
    events,
    flow,
    function_domains,
    functions,
    hints,
    keyword_usage,
    limits,
    line_length,
    missing_axis_values,
    operands,
    pow_index,
    print_format,
    soft_limits,
    startup,
    too_large_results,
    unused,
    v3_access,
    v3_keywords,
    values,
    zero_divisors,
)
from mintlang.analysis.traversal import Facts, LineParts, LineScope
from mintlang.controllers import ControllerProfile
from mintlang.diagnostics import Diagnostic
from mintlang.dialect import Dialect
from mintlang.records import record
from mintlang.semantic.carry import Meaning, control_meaning
from mintlang.syntax import nodes as n
from mintlang.syntax.lexer import PhysicalLines

_ALL_DIALECTS = frozenset(Dialect)


@record
class Rule:
    name: str
    check: Callable[[Facts], Iterator[Finding]] | None = None
    each_line: Callable[[LineScope], Iterator[Finding]] | None = None
    each_text_line: Callable[[PhysicalLines, range, ControllerProfile, Dialect], Iterator[Diagnostic]] | None = None
    dialects: frozenset[Dialect] = _ALL_DIALECTS
    reads: Meaning | None = None  # what a whole-application rule reads of a line, where less than all it means
    looks_at: LineParts | None = None  # what a line rule reads of a line: skipped on lines without any (None: all)

    @property
    def summary(self) -> str:
        """The first line of the rule module's docstring."""
        function = self.check or self.each_line or self.each_text_line
        assert function is not None, f"rule {self.name} checks nothing"
        module = __import__(function.__module__, fromlist=["__doc__"])
        return (module.__doc__ or "").strip().splitlines()[0]


# Rules that read the keywords' v4 (and MintMT) attributes; v3 code is only read to be migrated.
_V4_ATTRIBUTES = frozenset({Dialect.V4, Dialect.MINTMT})

RULES: tuple[Rule, ...] = (
    Rule("declarations", declarations.check, declarations.each_line, looks_at=LineParts(frozenset({n.Define}))),
    Rule(
        "keyword-usage",
        each_line=keyword_usage.each_line,
        dialects=_V4_ATTRIBUTES,
        looks_at=LineParts(frozenset({n.BareName}), keyword_uses=True),
    ),
    Rule(
        "addressing",
        addressing.check,
        addressing.each_line,
        dialects=_V4_ATTRIBUTES,
        looks_at=LineParts(frozenset({n.Axes, n.FunctionStatement}), keyword_uses=True),  # CAMTABLE(axis, ...)
    ),
    Rule("values", each_line=values.each_line, dialects=_V4_ATTRIBUTES, looks_at=LineParts(keyword_uses=True)),
    Rule(
        "empty-values",
        each_line=empty_values.each_line,
        looks_at=LineParts(frozenset({n.Pause, n.KeywordStatement, n.FunctionStatement})),
    ),
    Rule(
        "missing-axis-values",
        each_line=missing_axis_values.each_line,
        dialects=frozenset({Dialect.V3, Dialect.V4}),  # MintMT's guide does not say how its (0,1) shares values
        looks_at=LineParts(keyword_uses=True),
    ),
    Rule(
        "operands",
        each_line=operands.each_line,
        dialects=_V4_ATTRIBUTES,
        looks_at=LineParts(frozenset({n.KeywordStatement})),
    ),
    Rule(
        "print-format",
        each_line=print_format.each_line,
        dialects=frozenset({Dialect.V4}),
        looks_at=LineParts(frozenset({n.Print, n.KeywordStatement, n.Input})),
    ),
    Rule(
        "functions",
        each_line=functions.each_line,
        dialects=_V4_ATTRIBUTES,  # MintMT's MOVER(0) is a keyword's axis, no call
        looks_at=LineParts(calls=True),  # a function written as a statement is one of the line's calls
    ),
    Rule(
        "function-domains",
        each_line=function_domains.each_line,
        dialects=frozenset({Dialect.V4, Dialect.MINTMT}),  # Mint v3 has none of these functions
        looks_at=LineParts(calls=True),
    ),
    Rule(
        "pow-index",
        each_line=pow_index.each_line,
        dialects=frozenset({Dialect.V4, Dialect.MINTMT}),  # Mint v3 has no POW
        looks_at=LineParts(calls=True),
    ),
    Rule(
        "v3-access",
        each_line=v3_access.each_line,
        dialects=frozenset({Dialect.V3}),
        looks_at=LineParts(frozenset({n.Axes}), keyword_uses=True),
    ),
    Rule(
        "arrays",
        arrays.check,
        arrays.each_line,
        looks_at=LineParts(frozenset({n.Dim, n.Input}), calls=True),  # COMMS(i) = v is a call
    ),
    # The v3 guide lists no error 2021, and mint-run does not simulate a v3 division by zero
    Rule(
        "zero-divisors",
        each_line=zero_divisors.each_line,
        dialects=frozenset({Dialect.V4, Dialect.MINTMT}),
        looks_at=LineParts(arithmetic=True),  # its divisions
    ),
    Rule(
        "too-large-results",
        each_line=too_large_results.each_line,
        dialects=frozenset({Dialect.V4, Dialect.MINTMT}),  # v3's numbers are not binary32 (the lexer's note)
        looks_at=LineParts(arithmetic=True),
    ),
    Rule("events", events.check, reads=control_meaning),
    Rule(
        "v3-keywords",
        v3_keywords.check,
        v3_keywords.each_line,
        looks_at=LineParts(frozenset({n.BareName}), keyword_uses=True),
    ),
    Rule("flow", flow.check, reads=control_meaning),
    Rule("calls", calls.check, reads=control_meaning),
    Rule("limits", limits.check),
    Rule("soft-limits", soft_limits.check, dialects=frozenset({Dialect.V4})),
    Rule("line-length", each_text_line=line_length.each_text_line),
    Rule("startup", startup.check, reads=control_meaning),
    Rule("collisions", collisions.check),
    Rule("unused", unused.check),
    Rule(
        "hints",
        each_line=hints.each_line,
        dialects=frozenset({Dialect.V4}),  # MintMT's (0) is not v4's [0]
        looks_at=LineParts(keyword_uses=True),
    ),
)
