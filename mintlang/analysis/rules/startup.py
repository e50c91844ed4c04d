"""AUTO and PROTECT placed where the controller ignores them.

AUTO runs the configuration and the program at power-up only when it is the
very first command of the configuration file, before any REM; anywhere else
in either file it is ignored (v4 guide, AUTO), so a machine that should start
on its own would sit at the prompt: W114. Where the controller has no AUTO at
all, error 17 says so instead. ``PROTECT <password>`` belongs on the first line
of the program file, before any comment, "similar to AUTO in the configuration
buffer" (000:5291-5292, 000:15393): elsewhere it protects nothing, W114 too.
Writing PROTECT (``PROTECT = _on``) turns the checking on and off from
anywhere (000:15420-15423).
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, own
from mintlang.analysis.traversal import Facts
from mintlang.keyworddb import database
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n
from mintlang.syntax.tokens import BYTE_ORDER_MARK


def check(facts: Facts) -> Iterator[Finding]:
    model = facts.model
    has_auto = database().keywords["AUTO"].available_on(model.controller.controller)
    configuration = model.configuration.source if model.configuration else ""
    if not facts.may_name(*(("AUTO", "PROTECT") if has_auto else ("PROTECT",))):
        return  # a word in neither file, nor in a macro's text there: no keyword use to walk to (most checks)
    for line, use in facts.keyword_uses():
        word = use.keyword.keyword
        if word == "AUTO" and has_auto:
            span = line.span(use.keyword.spelling_span)
            detail = _misplaced("AUTO", use.unit, Unit.CONFIGURATION, configuration, span.start)
        elif word == "PROTECT" and _sets_a_password(use.statement):
            span = line.span(use.keyword.spelling_span)
            detail = _misplaced("PROTECT <password>", use.unit, Unit.PROGRAM, model.program.source, span.start)
        else:
            continue
        if detail is not None:
            yield Finding(use.unit, own("W114", span, detail))


def _misplaced(command: str, unit: Unit, home: Unit, home_source: str, offset: int) -> str | None:
    """Why ``command``, written in ``unit`` at ``offset``, is ignored: it is not the first thing in the file
    it belongs first in (``home``, whose text is ``home_source``); None when it is."""
    if unit is not home:
        return f"{command} in the {unit.value} file is ignored: it belongs first in the {home.value} file"
    if _text_before(home_source, offset):
        return f"{command} is ignored unless it is the first command of the {home.value} file, before any REM"
    return None


def _text_before(source: str, offset: int) -> bool:
    return bool(source[:offset].lstrip(BYTE_ORDER_MARK).strip())


def _sets_a_password(statement: n.Statement) -> bool:
    """``PROTECT <password>``, not ``PROTECT = _on``."""
    return isinstance(statement, n.KeywordStatement) and statement.values is None
