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
from mintlang.diagnostics import Edit, Fix, Span
from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Controller
from mintlang.keyworddb.usage import refusal
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n
from mintlang.syntax.lexer import comment_at

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
        addressed = ref.selector is not None and scope.dialect is not Dialect.MINTMT  # MintMT's (0,1) are axes too
        verdict = _verdict(
            ref.keyword,
            ref.spelling,
            controller,
            use.use,
            has_arguments,
            addressed=addressed,
            dot=addressed and ref.selector is not None and ref.selector.dot,
            dialect=scope.dialect,
        )
        if verdict is not None:
            code, detail = verdict
            fixes = (
                _spelling_fix(ref.spelling, controller, ref.spelling_span, scope.dialect, addressed=addressed)
                if code == 3007 and scope.writes(ref.spelling_span, ref.spelling)
                else ()
            )
            yield Finding(unit, mint_error(code, ref.spelling_span, detail, fixes=fixes))
    db = database()
    for statement in scope.facts.statements:
        if isinstance(statement, n.BareName) and db.rename_of(statement.name.text) is None:  # else: v3_keywords
            word = statement.name.text
            written = scope.writes(statement.name.span, word)
            label = label_written_with_a_colon(scope.syntax.text, statement.name.span) if written else None
            if label is not None:
                detail = f"'{word}' is not a keyword (a label is written #{word}, first on its line)"
                fixes: tuple[Fix, ...] = (label,)
            else:
                fixes = (
                    _spelling_fix(word, controller, statement.name.span, scope.dialect, alone=True) if written else ()
                )
                detail = _not_a_keyword(word, controller, scope.dialect, alone=True)
            yield Finding(unit, mint_error(3007, statement.span, detail, fixes=fixes))


def label_written_with_a_colon(text: str, name: Span) -> Fix | None:
    """The fix that writes other BASICs' label ``Init:``, a name first on its line before a colon, as Mint's
    ``#Init`` (000:1843-1844, 1871-1872); safe where only a comment follows, the colon going with the hash."""
    if text[: name.start].strip() or not text[name.end :].lstrip(" \t").startswith(":"):
        return None
    colon = text.index(":", name.end)
    rest = text[colon + 1 :].strip()
    if not rest or comment_at(rest, 0):
        return Fix(
            "Write the label with a hash",
            (Edit(Span(name.start, colon + 1), f"#{text[name.start : name.end]}"),),
            safe=True,
        )
    return Fix("Write the label with a hash", (Edit(name, f"#{text[name.start : name.end]}"),))


def _not_a_keyword(
    word: str,
    controller: Controller,
    dialect: Dialect,
    *,
    addressed: bool = False,
    dot: bool = False,
    alone: bool = False,
) -> str:
    """Error 3007's detail, with the keyword ``word`` resembles if one does; a word written with axes
    (``arr[2]``) that resembles none that takes them is told where an index goes. A dot is how a keyword
    names a channel (``ADC.1``, 000:701-705), not an index: ``ANALOGIN.3`` is told that, not of arrays."""
    meant = _meant(word, controller, dialect, addressed=addressed, alone=alone)
    if meant is None and dot:
        return (
            f"'{word}' is not a keyword, so its dot addresses no channel or axis (a dot follows a keyword: "
            "ADC.1 reads analog input 1)"
        )
    if meant is None and addressed:
        return (
            f"'{word}' is not a keyword (an array is indexed in round brackets, {word}(index); square brackets "
            "and a dot address a keyword's axes or channel)"
        )
    return not_a_keyword(word, meant, alone=alone)


def _meant(word: str, controller: Controller, dialect: Dialect, *, addressed: bool, alone: bool = False) -> str | None:
    """The keyword ``word`` resembles; written with axes or a channel, only one that takes them
    (000:1063-1066: ``arr[2]`` resembles ERR, which takes neither; ``GOO.0`` is GO, not GOTO)."""
    return keyword_like(word.upper(), controller, dialect=dialect, axes=addressed, alone=alone)


def _spelling_fix(
    word: str, controller: Controller, span: Span, dialect: Dialect, *, addressed: bool = False, alone: bool = False
) -> tuple[Fix, ...]:
    """Write the keyword ``word`` resembles, if one does."""
    meant = _meant(word, controller, dialect, addressed=addressed, alone=alone)
    return (Fix.replace(span, meant),) if meant is not None else ()


@cache
def _verdict(
    name: str,
    spelling: str,
    controller: Controller,
    use: Use,
    has_arguments: bool,
    *,
    addressed: bool,
    dot: bool,
    dialect: Dialect,
) -> tuple[int, str] | None:
    """What is wrong with this use of a keyword, if anything (the same for every such use: cached): a word
    that is no keyword here, else what the keyword's record says of the use, as ``mint-run`` says it too."""
    keyword = database().keywords_of(dialect).get(name)
    if keyword is None:
        if dialect.modern and successor(spelling.upper(), profile(controller)) is not None:
            return None  # an old v3 keyword: the v3-keyword rule names its replacement
        return 3007, _not_a_keyword(spelling, controller, dialect, addressed=addressed, dot=dot)
    return refusal(keyword, controller, dialect, use, has_arguments=has_arguments)
