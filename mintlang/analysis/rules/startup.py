"""AUTO placed where the controller ignores it.

AUTO runs the configuration and the program at power-up only when it is the
very first command of the configuration file, before any REM; anywhere else
in either file it is ignored (v4 guide, AUTO), so a machine that should start
on its own would sit at the prompt: W114. Where the controller has no AUTO at
all, error 17 says so instead.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, own
from mintlang.analysis.traversal import Facts
from mintlang.keyworddb import database
from mintlang.semantic.units import Unit
from mintlang.syntax.tokens import BYTE_ORDER_MARK


def check(facts: Facts) -> Iterator[Finding]:
    model = facts.model
    if model.controller.controller not in database().keywords["AUTO"].controllers:
        return
    for line, use in facts.keyword_uses():
        if use.keyword.keyword != "AUTO":
            continue
        span = line.span(use.keyword.spelling_span)
        if use.unit is Unit.PROGRAM:
            detail = "AUTO in the program file is ignored: it belongs first in the configuration file"
        elif _text_before(model.configuration.source if model.configuration else "", span.start):
            detail = "AUTO is ignored unless it is the first command of the configuration file, before any REM"
        else:
            continue
        yield Finding(use.unit, own("W114", span, detail))


def _text_before(source: str, offset: int) -> bool:
    return bool(source[:offset].lstrip(BYTE_ORDER_MARK).strip())
