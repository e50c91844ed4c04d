"""What an expectation looks at: a keyword, a variable or an array element, spelt one way.

Users write ``pos.0``, ``PS.0`` or ``OUT3``; the simulator should answer one
spelling only, so every target is made canonical here: upper case, the
keyword's full name, an axis or channel as ``.n`` and indexes as ``(i,j)``.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from mintlang.keyworddb import database
from mintlang.keyworddb.model import Addressing, KeywordKind
from mintlang.runtime.scenario.problems import Invalid

_TARGET = re.compile(
    r"(?P<name>[A-Za-z_][A-Za-z0-9_]*)"
    r"(?:\.(?P<dot>[0-9]+)|\((?P<indexes>\s*-?[0-9]+\s*(?:,\s*-?[0-9]+\s*)*)\))?"
)
_GLUED_CHANNEL = re.compile(r"[0-9]+$")


@dataclass(frozen=True, slots=True)
class Target:
    """A canonical target; ``every_axis`` when an axis keyword was written without its axis."""

    text: str
    every_axis: bool

    def on_axis(self, axis: int) -> str:
        return f"{self.text}.{axis}"


def target(written: str) -> Target:
    """The canonical form of ``written``, or ``Invalid`` saying why it names nothing readable."""
    found = _TARGET.fullmatch(written.strip())
    if found is None:
        raise Invalid(f"{written!r} is not a keyword, variable or array element (e.g. POS.0, count, table(3))")
    name, dot, indexes = found["name"].upper(), found["dot"], found["indexes"]
    suffix = "" if indexes is None else "(" + ",".join(str(int(i)) for i in indexes.split(",")) + ")"
    keyword = database().lookup(name)
    if keyword is None:
        if dot is not None:
            raise Invalid(f"{found['name']} is not a keyword, so it takes no .{dot}")
        return Target(name + suffix, every_axis=False)
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
