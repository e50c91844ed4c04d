"""Loading a parser builds the grammar's rules from the shipped serialization itself, by their
constructors (``grammar.decoded_rules``), instead of lark's generic deserialization: it must make
exactly what lark makes of the same data, and leave lark to build the parser from an unknown shape."""

from __future__ import annotations

from typing import Any

import pytest

from mintlang.dialect import Dialect
from mintlang.syntax import grammar
from mintlang.syntax.lark_runtime import Rule, RuleOptions, SerializeMemoizer, Symbol, Terminal, TerminalDef


def _described(symbol: Symbol) -> tuple[object, ...]:
    return (type(symbol), symbol.name, symbol.filter_out if isinstance(symbol, Terminal) else None)


def _rule(rule: Rule) -> tuple[object, ...]:
    options = rule.options
    return (
        type(rule),
        _described(rule.origin),
        type(rule.expansion),
        [_described(symbol) for symbol in rule.expansion],
        rule.order,
        rule.alias,
        type(options),
        (options.keep_all_tokens, options.expand1, options.priority, options.template_source, options.empty_indices),
        hash(rule),
    )


def _memo(dialect: Dialect) -> dict[int, Any]:
    memo: dict[int, Any] = grammar.shipped_tables(dialect)["parser"]["memo"]
    return memo


@pytest.mark.parametrize("dialect", list(Dialect))
def test_the_rules_are_what_lark_deserializes(dialect: Dialect) -> None:
    by_lark = SerializeMemoizer.deserialize(_memo(dialect), {"Rule": Rule, "TerminalDef": TerminalDef}, {})
    decoded = grammar.decoded_rules(_memo(dialect))
    assert list(decoded) == list(by_lark)
    assert [_rule(rule) for rule in decoded.values()] == [_rule(rule) for rule in by_lark.values()]


@pytest.mark.parametrize(
    "change",
    [
        pytest.param(lambda rule: rule.update(__type__="TerminalDef"), id="not-a-rule"),
        pytest.param(lambda rule: rule["origin"].update(__type__="Pattern"), id="unknown-symbol"),
        pytest.param(lambda rule: rule["options"].pop("expand1"), id="missing-option"),
    ],
)
def test_an_unknown_shape_is_refused_for_lark_to_build_the_parser(change: Any) -> None:
    memo = _memo(Dialect.V4)
    first = next(iter(memo))
    copied = {**memo[first], "origin": dict(memo[first]["origin"]), "options": dict(memo[first]["options"])}
    change(copied)
    with pytest.raises(KeyError):  # _parser catches it and has lark compute the tables
        grammar.decoded_rules({first: copied})


def test_rule_options_are_all_read() -> None:
    assert RuleOptions.__serialize_fields__ == (
        "keep_all_tokens",
        "expand1",
        "priority",
        "template_source",
        "empty_indices",
    )
