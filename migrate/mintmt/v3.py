"""Telling a Mint v3 application given to ``--to mintmt``, which reads Mint v4: it is refused, not rewritten.

Read as v4, a v3 program keeps its v3 keywords (``HMSPEED``, ``CONTON``, ``#FASTPOS``), and the
MintMT rewrite would copy them into a file MintMT rejects on each of those lines. What shows v3 is
what the v4 checker finds on such a word: a name v4 does not know (an undeclared variable, an
unknown keyword, E3001/E3007) spelt as the full name of a v3 keyword v4 does not have or as a v3
constant (``CONFIG = _servo``), or a v3 event (W102); and such a name written with v3's ``;`` fill
(``HMSPEED = 10;``), where the check stops on the ``;`` before it names the variable. An abbreviation
read as a variable is not enough (``ax`` is v3's AUX, and a likely v4 name), and a v4 program that
declares a variable so named (``DIM conton``) gets no finding on it; one written as a keyword, with an
axis (``BA.2 = 5``) or alone as a command (``DL``), is no v4 name: the check says it is v3's (E3007).
"""

from __future__ import annotations

from collections.abc import Collection

import mintlang
from mintlang.diagnostics import Diagnostic, LineIndex, split_lines
from mintlang.keyworddb import database
from mintlang.migrate.context import MARKER_LINE
from mintlang.migrate.rules.addressed import unparsed_write
from mintlang.records import record
from mintlang.syntax import nodes as n

_UNKNOWN_KEYWORD = "E3007"
_UNKNOWN_NAME = frozenset({"E3001", _UNKNOWN_KEYWORD})
_SYNTAX = "E2003"
_NAMED = _UNKNOWN_NAME | {_SYNTAX}
_V3_EVENT = "W102"


@record
class V3Uses:
    """What shows v3 in an application: the v3 keywords v4 does not know, each once, in the order found (the
    configuration file's first, as the two are checked together), and whether every use of them is on a line
    ``mint-migrate`` flagged (a ``REM MIGRATE:`` line right above it): the v3 -> v4 migration is then done,
    and what is left of v3 waits for a person."""

    words: tuple[str, ...]
    left_for_a_person: bool


def v3_uses(source: str, config: str | None = None) -> V3Uses:
    """The application's uses of v3 words, found by one Mint v4 check of it."""
    analysis = mintlang.check_application(source, dialect="v4", config=config)
    found: list[tuple[str, bool]] = []  # each use, and whether a marker flags its line
    for text, diagnostics in ((config or "", analysis.configuration), (source, analysis.program)):
        index = LineIndex(text)
        lines = split_lines(text)
        for diagnostic in diagnostics:
            word = text[diagnostic.span.start : diagnostic.span.end]
            if diagnostic.code == _SYNTAX:
                word = _filled(index, text, diagnostic.span.start, analysis.model.symbols.variables.keys())
            if _shows_v3(diagnostic, word):
                above = index.position(diagnostic.span.start).line - 2  # the line above, counted from 0
                found.append((word.upper(), above >= 0 and MARKER_LINE.match(lines[above]) is not None))
    words = tuple(dict.fromkeys(word for word, _ in found))
    return V3Uses(words, bool(found) and all(marked for _, marked in found))


def _shows_v3(diagnostic: Diagnostic, word: str) -> bool:
    """Whether the v4 check's ``diagnostic`` on ``word`` shows v3: a v3 event, a v3 keyword written as a keyword
    (its abbreviation too), or a v3 keyword's full name or a v3 constant v4 reads as a variable."""
    if diagnostic.code == _V3_EVENT or (diagnostic.code == _UNKNOWN_KEYWORD and diagnostic.from_v3):
        return True
    return diagnostic.code in _NAMED and _v3_only(word)


def _filled(index: LineIndex, text: str, error: int, declared: Collection[str]) -> str:
    """The undeclared name a statement the check stopped in writes (``HMSPEED = 10;``: v4 takes the
    name for a variable, which no ``;`` fill follows), or nothing."""
    line = index.position(error).line
    statement = text[index.line_start(line) : error].rsplit(":", 1)[-1]
    word = unparsed_write(statement)
    return "" if word is None or n.identity(word) in declared else word


def _v3_only(word: str) -> bool:
    """A name v4 does not know that is the full name of a v3 keyword v4 does not have, or a v3 constant
    (``_servo``, v4's ``_cfSERVO``): no v4 name starts with ``_`` but a constant's."""
    db = database()
    if word.startswith("_"):
        return word.upper() in db.v3_constants
    keyword = db.lookup_v3(word)
    return keyword is not None and keyword.name == word.upper() and db.lookup(word) is None
