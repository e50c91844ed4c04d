"""What an expectation looks at: a keyword, a variable or an array element, spelt one way.

Users write ``pos.0``, ``PS.0`` or ``OUT3``; the simulator should answer one
spelling only, so every target is made canonical here: upper case, the
keyword's full name, an axis or channel as ``.n`` and indexes as ``(i,j)``.
A Mint v3 program's targets are its own keywords (``MODE.0``, ``GN.1``, ``IN3``).
"""

from __future__ import annotations

import re

from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Addressing, KeywordKind, V3Keyword
from mintlang.records import record
from mintlang.runtime.scenario.problems import Invalid

_TARGET = re.compile(
    r"(?P<name>[A-Za-z_][A-Za-z0-9_]*)"
    r"(?:\.(?P<dot>[0-9]+)|\((?P<indexes>\s*-?[0-9]+\s*(?:,\s*-?[0-9]+\s*)*)\))?"
)
_GLUED_CHANNEL = re.compile(r"[0-9]+$")


@record
class Target:
    """A canonical target; ``every_axis`` when an axis keyword was written without its axis. ``shown`` is how
    reports name it: a variable as the program spells it (``myCount``), a keyword by its full name."""

    text: str
    every_axis: bool
    shown: str = ""

    @property
    def name(self) -> str:
        return self.shown or self.text

    def on_axis(self, axis: int) -> str:
        return f"{self.text}.{axis}"


def target(written: str, dialect: Dialect = Dialect.V4) -> Target:
    """The canonical form of ``written`` in a program of ``dialect``, or ``Invalid`` saying why it names
    nothing readable."""
    found = _TARGET.fullmatch(written.strip())
    if found is None:
        raise Invalid(f"{written!r} is not a keyword, variable or array element (e.g. POS.0, count, table(3))")
    name, dot, indexes = found["name"].upper(), found["dot"], found["indexes"]
    suffix = "" if indexes is None else "(" + ",".join(str(int(i)) for i in indexes.split(",")) + ")"
    if dialect is Dialect.V3:
        return _v3_target(found["name"], name, dot, suffix)
    db = database()
    keyword = (db.mintmt_keywords.get(name) if dialect is Dialect.MINTMT else None) or db.lookup(name)
    if keyword is None:
        return _variable(found["name"], name, dot, suffix)
    if keyword.kind is not KeywordKind.PARAMETER:
        raise Invalid(f"{keyword.name} is a {keyword.kind.value}, not a value to expect")
    spellings = {keyword.name.upper(), *(abbreviation.upper() for abbreviation in keyword.abbreviations)}
    glued = _GLUED_CHANNEL.search(name) if name not in spellings else None
    if glued is not None:
        dot = glued[0]
    if dot is not None and keyword.addressing is Addressing.NONE:
        raise Invalid(f"{keyword.name} has no axis or channel, so it takes no .{dot}")
    if dot is not None:
        return Target(f"{keyword.name}.{int(dot)}{suffix}", every_axis=False)
    every_axis = keyword.addressing is Addressing.AXIS and not suffix
    return Target(keyword.name + suffix, every_axis)


def _variable(written: str, name: str, dot: str | None, suffix: str) -> Target:
    if dot is not None:
        raise Invalid(f"{written} is not a keyword, so it takes no .{dot}")
    return Target(name + suffix, every_axis=False, shown=written + suffix)


def _v3_target(written: str, name: str, dot: str | None, suffix: str) -> Target:
    """A v3 keyword by its v3 name; ``IN`` and ``OUT``, which have bit keywords (``IN3``), take a bit as ``.n``."""
    keyword = database().lookup_v3(name)
    if keyword is None:
        return _variable(written, name, dot, suffix)
    if not keyword.read:
        raise Invalid(f"{keyword.name} cannot be read in Mint v3, so it is not a value to expect")
    if dot is not None and keyword.addressing is Addressing.NONE and not _has_bits(keyword):
        raise Invalid(f"{keyword.name} has no axis or channel, so it takes no .{dot}")
    if dot is not None:
        return Target(f"{keyword.name}.{int(dot)}{suffix}", every_axis=False)
    return Target(keyword.name + suffix, keyword.addressing is Addressing.AXIS and not suffix)


def _has_bits(keyword: V3Keyword) -> bool:
    return database().lookup_v3(keyword.name + "0") is not None
