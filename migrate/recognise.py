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

So an application is taken as Mint v4 when the rewrite rules find nothing to
rewrite in it and one of its files shows such a form. A file that reads the same
in both versions (no variable, no v4-only keyword) cannot be told from a v3
original, and is migrated as one: the notes come back rather than being lost.
"""

from __future__ import annotations

import re
from collections import defaultdict
from collections.abc import Iterable, Mapping

import mintlang
from mintlang.keyworddb import database
from mintlang.semantic.index import KeywordUse, Use
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n

_NOTE = re.compile(r"^[ \t]*REM\b.*\bby mint-migrate[ \t]*$", re.IGNORECASE | re.MULTILINE)


def shows_v4(texts: Mapping[Unit, str], controller: str) -> bool:
    """Whether the files (configuration, program) show a form only Mint v4 has."""
    if any(_NOTE.search(text) for text in texts.values()):
        return True
    configuration = None
    if Unit.CONFIGURATION in texts:
        configuration = mintlang.parse(texts[Unit.CONFIGURATION], "v4")
    program = mintlang.parse(
        texts[Unit.PROGRAM], "v4", macros=configuration.macros if configuration is not None else None
    )
    model = mintlang.build_model(program, configuration, controller)
    if any(isinstance(statement, n.Dim) and statement.size is None for _, _, statement in model.index.statements):
        return True
    return _v4_only_keyword(model.index.keyword_uses)


def _v4_only_keyword(uses: Iterable[KeywordUse]) -> bool:
    """Whether a v4 keyword v3 did not have is used other than as a v3 user variable would be (a
    word neither version knows, as the v3 guide's ``X2.0 = 0`` for XIO2 is to the readers, shows nothing):
    a read counts as a variable's only outside the name's own assignments (``x = x | 128``
    reads ``x`` before v3 declares it, and is what the migrator writes for input modes)."""
    db = database()
    v4_only = [use for use in uses if use.keyword.keyword in db.keywords and db.lookup_v3(use.keyword.keyword) is None]
    assigning = {(use.keyword.keyword, use.unit, use.statement.span) for use in v4_only if use.use is Use.WRITE}
    forms: dict[str, set[Use | None]] = defaultdict(set)
    for use in v4_only:
        own_assignment = use.use is Use.READ and (use.keyword.keyword, use.unit, use.statement.span) in assigning
        forms[use.keyword.keyword].add(use.use if _plain(use) and not own_assignment else None)
    return any(found != {Use.READ, Use.WRITE} for found in forms.values())


def _plain(use: KeywordUse) -> bool:
    """Whether the keyword is written as a plain name read or assigned, as a variable is."""
    return use.keyword.selector is None and use.keyword.channel is None and use.use in (Use.READ, Use.WRITE)
