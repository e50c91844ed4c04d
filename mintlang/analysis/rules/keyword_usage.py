"""Keywords used the way their attributes allow.

Writing a keyword that is read-only or a command is error 2000 (``CAMINDEX = 4``);
reading one that is write-only is 2002 (``PRINT ACCELTIME``); naming a
parameter on its own as a statement is 2005 (``SPEED``); operands after a command
that takes only axes are 2003 (``STOP following``, a comment missing its REM); editor commands in a
program are 2006 (``NEW``), but for RELEASE in a configuration file, where the
manual recommends it, and for the buffer ``RUN`` names (``RUN PROG``, ``RUN CON``,
000:15723-15733); a word that is no keyword of the target controller is 3007.
The keyword's record decides the rest (``mintlang.keyworddb.usage``), as in ``mint-run``.
"""

from __future__ import annotations

from collections.abc import Iterator
from functools import cache

from mintlang.analysis.findings import Finding, mint_error
from mintlang.analysis.rules.v3_keywords import successor
from mintlang.analysis.suggestions import keyword_like, not_a_keyword
from mintlang.analysis.traversal import LineScope, Use
from mintlang.controllers import profile
from mintlang.diagnostics import Fix, Span
from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Controller
from mintlang.keyworddb.usage import refusal
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n

_CONFIGURATION_COMMANDS = frozenset({"RELEASE"})  # clears the variables before each run (000:935-939)
_BUFFERS = frozenset({"PROG", "CON"})  # what RUN runs; at the command line they are editor commands


def each_line(scope: LineScope) -> Iterator[Finding]:
    controller = scope.controller.controller
    unit = scope.unit
    for use in scope.facts.keyword_uses:
        ref = use.keyword
        if unit is Unit.CONFIGURATION and ref.keyword in _CONFIGURATION_COMMANDS:
            continue
        statement = use.statement
        if ref.keyword in _BUFFERS and isinstance(statement, n.KeywordStatement) and statement.keyword.keyword == "RUN":
            continue
        has_arguments = isinstance(statement, n.KeywordStatement) and bool(statement.arguments)
        verdict = _verdict(ref.keyword, ref.spelling.upper(), controller, use.use, has_arguments, dialect=scope.dialect)
        if verdict is not None:
            code, detail = verdict
            fixes = (
                _spelling_fix(ref.spelling.upper(), controller, ref.spelling_span, scope.dialect)
                if code == 3007
                else ()
            )
            yield Finding(unit, mint_error(code, ref.spelling_span, detail, fixes=fixes))
    db = database()
    for statement in scope.facts.statements:
        if isinstance(statement, n.BareName) and db.rename_of(statement.name.text) is None:  # else: v3_keywords
            word = statement.name.text
            fixes = _spelling_fix(word, controller, statement.name.span, scope.dialect)
            detail = _not_a_keyword(word, controller, scope.dialect)
            yield Finding(unit, mint_error(3007, statement.span, detail, fixes=fixes))


def _not_a_keyword(word: str, controller: Controller, dialect: Dialect) -> str:
    """Error 3007's detail, with the keyword ``word`` resembles if one does."""
    return not_a_keyword(word, keyword_like(word.upper(), controller, dialect=dialect))


def _spelling_fix(word: str, controller: Controller, span: Span, dialect: Dialect) -> tuple[Fix, ...]:
    """Write the keyword ``word`` resembles, if one does."""
    meant = keyword_like(word.upper(), controller, dialect=dialect)
    return (Fix.replace(span, meant),) if meant is not None else ()


@cache
def _verdict(
    name: str, spelling: str, controller: Controller, use: Use, has_arguments: bool, *, dialect: Dialect
) -> tuple[int, str] | None:
    """What is wrong with this use of a keyword, if anything (the same for every such use: cached): a word
    that is no keyword here, else what the keyword's record says of the use, as ``mint-run`` says it too."""
    keyword = database().keywords_of(dialect).get(name)
    if keyword is None:
        if dialect.modern and successor(spelling, profile(controller)) is not None:
            return None  # an old v3 keyword: the v3-keyword rule names its replacement
        return 3007, _not_a_keyword(spelling, controller, dialect)
    return refusal(keyword, controller, dialect, use, has_arguments=has_arguments)
