"""Telling an application already in Mint v4 from a v3 one, so that a run leaves it alone.

The rewrite rules already leave v4 text as it is; the notes and markers would not:
a migrated file whose ``REM MIGRATE:`` lines were dealt with and removed would get
its prologue notes back, as any v3 program that needs no rewrite does. What tells
the two apart is a form v3 could not have written:

* a scalar ``DIM``: v3's DIM declares arrays only (v3:7304), v4 wants every
  variable declared (v4:897-910), and the migrator declares each one it finds;
* a v4 keyword that v3 did not have (``HOMESPEED``, ``POSTARGET``), as the v4 reader
  sees it, unless the v3 reader would take it for a user variable: assigned and read, and
  only ever written as a plain name (``homespeed = 0`` ... ``PRINT homespeed``). One with
  an axis or channel (``HOMESPEED.0``), as a command, read and never assigned (v3 declares
  a variable by its first assignment and rejects reading one it has not, v3:1352-1367,
  v3:1425-1429) or only assigned (what the migrator writes for a v3 ``HMSPEED = 10``) shows v4;
* a note the migrator wrote (``REM … removed by mint-migrate``).

Only one of these forms is also valid v3 with another meaning: a v4-only keyword that
is only ever assigned, as a plain name, is what a v3 user variable of that name looks
like (``inputactivelevel = 1``). The others are beyond doubt.

So an application is taken as Mint v4 when one of its files shows a form beyond doubt and Mint
v4 finds no error in it (a program ported by hand whose ``SIN`` already returns the v4 fraction
must not be scaled again), or when the rewrite rules find nothing to rewrite in it and one of its
files shows any such form. A file that reads the same in
both versions (no variable, no v4-only keyword) cannot be told from a v3 original, and
is migrated as one: the notes come back rather than being lost.

The migrator's marker (``REM MIGRATE:``) settles the one doubtful form: the migration renames every
v3 variable named as a v4 keyword (M-IDENT, ``kprop_u``), so in its output ``kprop = 10 : PRINT kprop``
(from v3's GAIN) is the keyword. A marked file is taken as Mint v4 when those renames (and their
DIMs) are all the rules would rewrite and Mint v4 finds no error in it: a run of some rules only
(``--only``, ``--skip``) marks a file that still holds v3, which another rule rewrites or the
check finds, and the next run migrates.
"""

from __future__ import annotations

import re
from collections import defaultdict
from collections.abc import Iterable, Mapping
from enum import IntEnum

import mintlang
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Controller
from mintlang.migrate.context import MARKER
from mintlang.semantic.index import KeywordUse, Use
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n

_MARKED = re.compile(rf"^[ \t]*{re.escape(MARKER)}", re.MULTILINE)
_NOTE = re.compile(r"^[ \t]*REM\b.*\bby mint-migrate[ \t]*$", re.IGNORECASE | re.MULTILINE)
_WORD = re.compile(r"#?[A-Za-z_]\w*")
_DIM_NAMES = re.compile(r"\bDIM\b([^:=\n]*)", re.IGNORECASE)  # up to a DIM's initial values
_NAME_WITHOUT_SIZE = re.compile(r"[A-Za-z_]\w*+(?![ \t]*+\()")


class Evidence(IntEnum):
    """How surely the files show Mint v4, weakest first."""

    NONE = 0
    SUGGESTED = 1  # a v4-only keyword only ever assigned, as a v3 user variable of that name would be
    BEYOND_DOUBT = 2


def marked(texts: Mapping[Unit, str]) -> bool:
    """Whether a file holds a line the migrator wrote for a person (``REM MIGRATE:``)."""
    return any(_MARKED.search(text) for text in texts.values())


def may_show_v4_beyond_doubt(texts: Mapping[Unit, str], controller: str) -> bool:
    """A look at the words alone that is never false where ``v4_evidence`` finds a form beyond
    doubt: a note, a name a DIM gives no size, or a word naming a v4 keyword v3 did not have.
    Reading a file as v4 costs about as much as migrating it again; most v3 files fail this."""
    for text in texts.values():
        if _NOTE.search(text) or any(_scalar(match.group(1)) for match in _DIM_NAMES.finditer(text)):
            return True
    db, target = database(), Controller(controller)
    words = {word.upper() for text in texts.values() for word in _WORD.findall(text)}
    return any(
        (keyword := db.lookup(word, target)) is not None and db.lookup_v3(keyword.name) is None for word in words
    )


def _scalar(declared: str) -> bool:
    """Whether a DIM's names (``a, b(10)``) hold one without a size."""
    return any(name.upper() != "OFFLINE" for name in _NAME_WITHOUT_SIZE.findall(declared))


def v4_evidence(texts: Mapping[Unit, str], controller: str) -> Evidence:
    """The strongest sign of Mint v4 the files (configuration, program) show."""
    if any(_NOTE.search(text) for text in texts.values()):
        return Evidence.BEYOND_DOUBT
    configuration = None
    if Unit.CONFIGURATION in texts:
        configuration = mintlang.parse(texts[Unit.CONFIGURATION], "v4")
    program = mintlang.parse(
        texts[Unit.PROGRAM], "v4", macros=configuration.macros if configuration is not None else None
    )
    model = mintlang.build_model(program, configuration, controller)
    if any(isinstance(statement, n.Dim) and statement.size is None for _, _, statement in model.index.statements):
        return Evidence.BEYOND_DOUBT
    return _v4_only_keyword(model.index.keyword_uses)


def shows_v4(texts: Mapping[Unit, str], controller: str) -> bool:
    """Whether the files (configuration, program) show a form only Mint v4 has."""
    return v4_evidence(texts, controller) is not Evidence.NONE


def valid_v4(texts: Mapping[Unit, str], controller: str) -> bool:
    """Whether Mint v4 finds no error in the files."""
    analysis = mintlang.check_application(
        texts[Unit.PROGRAM], controller=controller, config=texts.get(Unit.CONFIGURATION), select=("E",)
    )
    return not analysis.program and not analysis.configuration


def _v4_only_keyword(uses: Iterable[KeywordUse]) -> Evidence:
    """How surely a v4 keyword v3 did not have shows v4: beyond doubt when it is used other than as a
    v3 user variable would be (a word neither version knows, as the v3 guide's ``X2.0 = 0`` for XIO2
    is to the readers, shows nothing); suggested when it is only ever assigned, as a plain name, or
    written in a spelling v3 has too (``DE`` is v3's DECEL and v4's DRIVEENABLE). A read counts as a
    variable's only outside the name's own assignments (``x = x | 128`` reads ``x`` before v3
    declares it, and is what the migrator writes for input modes)."""
    db = database()
    v4_only = [use for use in uses if use.keyword.keyword in db.keywords and db.lookup_v3(use.keyword.keyword) is None]
    assigning = {(use.keyword.keyword, use.unit, use.statement.span) for use in v4_only if use.use is Use.WRITE}
    evidence = Evidence.NONE
    plain: dict[str, set[Use]] = defaultdict(set)
    for use in v4_only:
        own_assignment = use.use is Use.READ and (use.keyword.keyword, use.unit, use.statement.span) in assigning
        if db.lookup_v3(use.keyword.spelling) is not None:
            evidence = Evidence.SUGGESTED
        elif _plain(use) and not own_assignment:
            plain[use.keyword.keyword].add(use.use)
        else:
            return Evidence.BEYOND_DOUBT
    if any(found == {Use.READ} for found in plain.values()):
        return Evidence.BEYOND_DOUBT
    if any(found == {Use.WRITE} for found in plain.values()):
        return Evidence.SUGGESTED
    return evidence


def _plain(use: KeywordUse) -> bool:
    """Whether the keyword is written as a plain name read or assigned, as a variable is."""
    return use.keyword.selector is None and use.keyword.channel is None and use.use in (Use.READ, Use.WRITE)
