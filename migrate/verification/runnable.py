"""The texts the two runs are given: each application as written, less what would stop the comparison.

A statement ``mint-migrate`` leaves for a person (a manual item) often stays in
its v3 form, which v4 rejects: its compiler, and one such line stops the whole
v4 application before it starts, or the controller, when the line runs (a
keyword the platform lacks, such as ``AUTO`` on a NextMove). So a flagged line
``mint check`` finds in error is turned into a comment for the run (``REM`` in
front, the line numbers unchanged) and reported as disabled; it is not verified
either way. A flagged line is kept when disabling it would put another line in
error (the ``IF .. DO`` of a block, the line that declares a name): the v4 run
then stops on it, and the comparison is incomplete until a person deals with it.
A line in error that nobody flagged stays: the v4 run stops on it, and that is a
divergence. ``REM @expect`` lines are turned into plain comments in
both files: the comparison is the check, and a v3 expectation names v3 keywords
the v4 reader does not know.
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Mapping

import mintlang
from mintlang.diagnostics import split_lines
from mintlang.dialect import Dialect
from mintlang.migrate.model import MigrationResult
from mintlang.migrate.verification.model import Application, Place
from mintlang.semantic.units import Unit
from mintlang.syntax.lexer import lex

_EXPECT = re.compile(r"REM\s*@expect\b", re.IGNORECASE)
_COMMENT = "REM "


def original(result: MigrationResult) -> Application:
    """The v3 application the migration read."""
    configuration = result.configuration.source if result.configuration is not None else None
    return Application(without_expectations(result.source, Dialect.V3), _without(configuration, Dialect.V3))


def migrated(result: MigrationResult, controller: str) -> tuple[Application, tuple[Place, ...]]:
    """The v4 application, with the flagged lines in error disabled (and which those are)."""
    flagged = flagged_places(result)
    configuration = result.configuration.text if result.configuration is not None else None
    application = Application(without_expectations(result.text, Dialect.V4), _without(configuration, Dialect.V4))
    in_error = _in_error(application, controller)
    disabled: list[Place] = []
    tried: set[Place] = set()
    while candidates := sorted((in_error & flagged) - tried, key=_order):  # disabling one may bring out another
        place = candidates[0]
        tried.add(place)
        trial = _disable(application, place)
        found = _in_error(trial, controller)
        if found - flagged <= in_error - flagged:  # no line nobody flagged is put in error by it
            application, in_error = trial, found
            disabled.append(place)
    return application, tuple(sorted(disabled, key=_order))


def flagged_places(result: MigrationResult) -> set[Place]:
    """The lines of the migrated files that a manual item marks (application notes mark none)."""
    return {Place(unit.value, item.line) for unit, part in _parts(result) for item in part.manual if not item.note}


def origins(result: MigrationResult) -> Mapping[Place, frozenset[int]]:
    """The lines of the original each line of the migrated files was made from: its own where a run of lines
    is unchanged or rewritten line for line, every line of a run rewritten into more or fewer lines, none for
    a line the migrator added. Disabling a line (``migrated``) keeps the numbers, so they hold for the v4 run."""
    found: dict[Place, frozenset[int]] = {}
    for unit, part in _parts(result):
        old, new = split_lines(part.source), split_lines(part.text)
        for tag, i1, i2, j1, j2 in difflib.SequenceMatcher(None, old, new, autojunk=False).get_opcodes():
            if tag == "insert":
                continue
            whole = frozenset(range(i1 + 1, i2 + 1))
            for j in range(j1, j2):
                own = i2 - i1 == j2 - j1
                found[Place(unit.value, j + 1)] = frozenset((i1 + j - j1 + 1,)) if own else whole
    return found


def _order(place: Place) -> tuple[bool, int]:
    """The configuration file first (it runs first), then the program, each in line order."""
    return place.unit != Unit.CONFIGURATION.value, place.line


def _parts(result: MigrationResult) -> list[tuple[Unit, MigrationResult]]:
    parts = [(Unit.PROGRAM, result)]
    if result.configuration is not None:
        parts.append((Unit.CONFIGURATION, result.configuration))
    return parts


def _in_error(application: Application, controller: str) -> set[Place]:
    """The lines ``mint check`` finds a Mint error on, whether the compiler rejects them or they raise it
    when they run."""
    analysis = mintlang.check_application(application.program, controller=controller, config=application.configuration)
    found = set()
    for unit, document in analysis.model.documents():
        diagnostics = analysis.configuration if unit is Unit.CONFIGURATION else analysis.program
        for diagnostic in diagnostics:
            if diagnostic.mint_error is not None:
                found.add(Place(unit.value, document.line_index.position(diagnostic.span.start).line))
    return found


def _disable(application: Application, place: Place) -> Application:
    unit = Unit(place.unit)
    text = application.text(unit)
    assert text is not None, "a line is rejected in a file the application has"
    lines = split_lines(text, keepends=True)
    lines[place.line - 1] = _COMMENT + lines[place.line - 1]
    changed = "".join(lines)
    if unit is Unit.PROGRAM:
        return Application(changed, application.configuration)
    return Application(application.program, changed)


def without_expectations(text: str, dialect: Dialect) -> str:
    """``text`` with each ``REM @expect`` directive made a plain comment (same length, same lines)."""
    pieces = []
    offset = 0
    for start, line in lex(text, dialect).lines:
        if line.comment_start < 0:
            continue
        found = _EXPECT.match(line.text, line.comment_start, line.content_end)
        if found is not None:
            at = start + line.comment_start + found.group().index("@")
            pieces.append(text[offset:at])
            pieces.append(" ")
            offset = at + 1
    pieces.append(text[offset:])
    return "".join(pieces)


def _without(text: str | None, dialect: Dialect) -> str | None:
    return without_expectations(text, dialect) if text is not None else None
